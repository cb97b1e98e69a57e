#include "analytic/HalfSpaceFrequencyWavenumber.hpp"

#include "analytic/RayleighWave.hpp"

#include "core/Error.hpp"
#include "core/GaussLegendre.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstddef>
#include <mutex>
#include <string>
#include <utility>

namespace mfwave {

namespace {

using Complex = std::complex<Real>;

// e^w - 1 without cancellation for small |w|: Re = expm1(x) cos y - 2 sin^2(y/2), Im = e^x sin y.
Complex expm1(Complex w) {
  const Real x = w.real(), y = w.imag();
  const Real halfSine = std::sin(0.5 * y);
  return {std::expm1(x) * std::cos(y) - 2 * halfSine * halfSine, std::exp(x) * std::sin(y)};
}

// sin(w) / w, with its series near 0 (the removable singularity of the load's transform).
Complex sinc(Complex w) {
  if (std::abs(w) < 1e-4) return 1.0 - w * w / 6.0;
  return std::sin(w) / w;
}

// zeta(2m) for m >= 2: the sum to 100 and the Euler-Maclaurin estimate of the rest.
Real zetaEven(int m) {
  const Real power = 2.0 * m;
  Real sum = 0;
  for (int j = 1; j <= 100; ++j) sum += std::pow(static_cast<Real>(j), -power);
  const Real n = 100;
  return sum + std::pow(n, 1 - power) / (power - 1) - 0.5 * std::pow(n, -power) + power / 12 * std::pow(n, -power - 1);
}

// Li_2(e^w) for Re w <= 0, w != 0 (the image sums of the strip's quasi-static kernel).
// Far inside the unit disc the power series sum_j e^{jw} / j^2; otherwise, with Im w reduced to
// (-pi, pi], the expansion about w = 0 (|w| < 2 pi):
//   Li_2(e^w) = pi^2/6 + w - w log(-w) - w^2/4 + sum_{m >= 1} c_m w^{2m+1},
//   c_m = -B_2m / (2m (2m+1)!) = (-1)^m 2 zeta(2m) / ((2 pi)^2m 2m (2m+1)).
Complex dilogarithmOfExp(Complex w) {
  if (w.real() < -1) {
    const Complex q = std::exp(w);
    Complex sum = 0, power = 1;
    for (int j = 1; j < 200; ++j) {
      power *= q;
      const Complex add = power / static_cast<Real>(j * j);
      sum += add;
      if (std::abs(add) < 1e-17 * std::abs(sum)) break;
    }
    return sum;
  }
  const Real turns = std::round(w.imag() / (2 * kPi));
  w -= Complex(0, 2 * kPi * turns);
  if (std::abs(w) == 0) return kPi * kPi / 6;
  Complex sum = kPi * kPi / 6 + w - w * std::log(-w) - 0.25 * w * w;
  const Complex ratio = w * w / (4 * kPi * kPi);
  Complex power = w;  // w (w / 2pi)^{2m}
  for (int m = 1; m < 80; ++m) {
    power *= ratio;
    const Real zeta = m == 1 ? kPi * kPi / 6 : zetaEven(m);
    const Complex add = (m % 2 == 0 ? 2.0 : -2.0) * zeta / (2.0 * m * (2 * m + 1)) * power;
    sum += add;
    if (std::abs(add) < 1e-17 * std::abs(sum)) break;
  }
  return sum;
}

// The transfer below is the inner loop (frequencies x wavenumbers): the library's complex square
// root and division guard against infinities and overflow that cannot occur here (|k|, |s| < 1e6),
// so plain formulas, several times faster, replace them.
// Principal square root (Re >= 0; on the cut, the sign of Im z picks the side, as std::sqrt does).
Complex principalSqrt(Complex z) {
  const Real x = z.real(), y = z.imag();
  const Real t = std::sqrt(0.5 * (std::abs(x) + std::sqrt(x * x + y * y)));
  if (t == 0) return 0;
  return x >= 0 ? Complex(t, 0.5 * y / t) : Complex(0.5 * std::abs(y) / t, std::copysign(t, y));
}
Complex divide(Complex a, Complex b) { return a * std::conj(b) / std::norm(b); }

// The elastic medium's transfer T(k, z, s) of the header, as a function of q = k^2 and s^2.
struct Medium {
  Real inverseAlpha2, inverseBeta2, mu;

  Complex transfer(Complex q, Complex s2, Real z) const {
    const Complex sp = s2 * inverseAlpha2, ss = s2 * inverseBeta2;
    const Complex nuP = principalSqrt(q + sp), nuS = principalSqrt(q + ss);
    const Complex a = 2.0 * q + ss;
    // (2k^2 + s^2/beta^2) e^{-nu_p z} - 2k^2 e^{-nu_s z}, its two large terms cancelling for
    // k >> |s|: written with e^{-nu_p z} - e^{-nu_s z} = e^{-nu_s z} expm1((nu_s - nu_p) z),
    // nu_s - nu_p = (s^2/beta^2 - s^2/alpha^2) / (nu_s + nu_p).
    Complex bracket = ss;
    if (z > 0)
      bracket = ss * std::exp(-nuP * z) + 2.0 * q * std::exp(-nuS * z) * expm1(divide((ss - sp) * z, nuS + nuP));
    const Complex numerator = nuP * bracket;
    if (std::norm(q) <= 16 * std::norm(ss)) return divide(numerator, mu * (a * a - 4.0 * q * nuP * nuS));
    // For k >> |s| the Rayleigh function's two terms are ~4k^4 and their difference
    // ~2 k^2 s^2 (1/beta^2 - 1/alpha^2): rationalise, D = (a^4 - 16 q^2 nu_p^2 nu_s^2) /
    // (a^2 + 4 q nu_p nu_s), the first a polynomial in q with no cancellation there. (The
    // denominator vanishes only at |k| < |s| / beta, not here.)
    const Complex poly =
        ((16.0 * (ss - sp) * q + 8.0 * ss * (3.0 * ss - 2.0 * sp)) * q + 8.0 * ss * ss * ss) * q + ss * ss * ss * ss;
    return divide(numerator * (a * a + 4.0 * q * nuP * nuS), mu * poly);
  }
};

// Smallest even n' >= n whose factors are 2, 3, 5, 7 (fast FFT lengths).
long fftFriendly(long n) {
  for (long m = std::max<long>(n + (n & 1), 2);; m += 2) {
    long r = m;
    for (long p : {2, 3, 5, 7})
      while (r % p == 0) r /= p;
    if (r == 1) return m;
  }
}

// A(k) = int_0^2pi Xhat(k cos th, k sin th) dth for the square, Xhat = 4 l^2 sinc(k1 l) sinc(k2 l),
// at complex k (the square's path). The integrand is entire and 2pi-periodic in th, so the
// trapezoid rule converges geometrically once its M points exceed the angular band ~ sqrt2 |k| l
// (the Bessel-series order of e^{i sqrt2 k l cos(th - pi/4)}); M = 8m and the integrand's dihedral
// symmetry (th -> -th, th -> pi/2 - th) reduce the sum to [0, pi/4] with half weights at the ends.
Complex squareAngularIntegral(Complex k, Real l) {
  const int m = static_cast<int>(std::ceil((1.5 * std::sqrt(2.0) * std::abs(k) * l + 48) / 8));
  auto f = [&](Real th) { return sinc(k * l * std::cos(th)) * sinc(k * l * std::sin(th)); };
  Complex sum = 0.5 * (f(0) + f(0.25 * kPi));
  for (int j = 1; j < m; ++j) sum += f(0.25 * kPi * j / m);
  // (2pi / M) * 8 * sum * 4 l^2, M = 8m.
  return 2 * kPi / m * 4 * l * l * sum;
}

// FFTW buffers and a complex-to-real plan, released on scope exit. The planner is not thread-safe.
std::mutex& plannerMutex() {
  static std::mutex mutex;
  return mutex;
}

class InverseTransform {
 public:
  explicit InverseTransform(long n)
      : n_(n), in_(fftw_alloc_complex(static_cast<std::size_t>(n / 2 + 1))),
        out_(fftw_alloc_real(static_cast<std::size_t>(n))) {
    if (in_ == nullptr || out_ == nullptr) {
      release();
      throw Error("HalfSpaceFrequencyWavenumber: FFTW could not allocate " + std::to_string(n) + " samples");
    }
    {
      // FFTW_ESTIMATE plans without touching the buffers.
      std::lock_guard<std::mutex> lock(plannerMutex());
      plan_ = fftw_plan_dft_c2r_1d(static_cast<int>(n), in_, out_, FFTW_ESTIMATE);
    }
    if (plan_ == nullptr) {
      release();
      throw Error("HalfSpaceFrequencyWavenumber: FFTW could not plan a transform of " + std::to_string(n));
    }
  }
  ~InverseTransform() { release(); }
  InverseTransform(const InverseTransform&) = delete;
  InverseTransform& operator=(const InverseTransform&) = delete;

  // out[j] = sum_{n=0}^{N-1} Y_n e^{2 pi i n j / N} with Y_{N-n} = conj(Y_n), from Y_0..Y_{N/2}.
  const Real* run(const std::vector<Complex>& spectrum) {
    for (long i = 0; i <= n_ / 2; ++i) {
      in_[i][0] = spectrum[static_cast<std::size_t>(i)].real();
      in_[i][1] = spectrum[static_cast<std::size_t>(i)].imag();
    }
    fftw_execute(plan_);
    return out_;
  }

 private:
  void release() {
    if (plan_ != nullptr) {
      std::lock_guard<std::mutex> lock(plannerMutex());
      fftw_destroy_plan(plan_);
      plan_ = nullptr;
    }
    if (in_ != nullptr) fftw_free(in_);
    if (out_ != nullptr) fftw_free(out_);
    in_ = nullptr;
    out_ = nullptr;
  }
  long n_;
  fftw_complex* in_;
  Real* out_;
  fftw_plan plan_ = nullptr;
};

}  // namespace

HalfSpaceFrequencyWavenumber::HalfSpaceFrequencyWavenumber(Real lambda, Real mu, Real rho, SurfaceLoadShape shape,
                                                           Real halfWidth, std::vector<Real> times,
                                                           std::vector<Real> values, Real pressure,
                                                           FrequencyWavenumberSettings settings)
    : lambda_(lambda), mu_(mu), rho_(rho), alpha_(0), beta_(0), cR_(0), shape_(shape), l_(halfWidth),
      p_(pressure), load_(std::move(times), std::move(values)), settings_(settings) {
  if (!(mu_ > 0) || !std::isfinite(mu_)) throw InputError("mu", "must be positive and finite");
  if (!std::isfinite(lambda_) || !(lambda_ + mu_ > 0))
    throw InputError("lambda", "must be finite with lambda + mu > 0 (Poisson ratio above -1)");
  if (!(rho_ > 0) || !std::isfinite(rho_)) throw InputError("rho", "must be positive and finite");
  if (!(l_ > 0) || !std::isfinite(l_)) throw InputError("half_width", "must be positive and finite");
  if (!std::isfinite(p_)) throw InputError("pressure", "must be finite");
  const auto& s = settings_;
  if (!(s.periodFactor > 1) || !(s.periodFactor <= 100))
    throw InputError("settings.period_factor", "must be in (1, 100]");
  if (!(s.dampingPerPeriod >= 4) || !(s.dampingPerPeriod <= 60))
    throw InputError("settings.damping_per_period", "must be in [4, 60]");
  if (!(s.samplesPerTimeScale >= 4) || !(s.samplesPerTimeScale <= 1e5))
    throw InputError("settings.samples_per_time_scale", "must be in [4, 1e5]");
  if (!(s.taper >= 0) || !(s.taper < 1)) throw InputError("settings.taper", "must be in [0, 1)");
  if (!(s.wavenumberSpacing > 0) || !(s.wavenumberSpacing <= 1))
    throw InputError("settings.wavenumber_spacing", "must be in (0, 1]");
  if (!(s.cutoffFactor >= 0.5) || !(s.cutoffFactor <= 1e3))
    throw InputError("settings.cutoff_factor", "must be in [0.5, 1000]");
  alpha_ = std::sqrt((lambda_ + 2 * mu_) / rho_);
  beta_ = std::sqrt(mu_ / rho_);
  cR_ = mfwave::rayleighWaveSpeed(alpha_, beta_);
}

HalfSpaceFrequencyWavenumber::Series HalfSpaceFrequencyWavenumber::response(Real x, Real depth, Real endTime,
                                                                             Real dt) const {
  if (!std::isfinite(x)) throw InputError("x", "must be finite");
  if (shape_ == SurfaceLoadShape::Square && x != 0)
    throw InputError("x", "the square load is integrated on its axis only: x must be 0");
  if (!(depth >= 0) || !std::isfinite(depth)) throw InputError("depth", "must be >= 0 and finite");
  if (!(endTime > 0) || !std::isfinite(endTime)) throw InputError("end_time", "must be positive and finite");
  if (!(dt > 0) || !(dt <= endTime)) throw InputError("dt", "must be in (0, end_time]");
  const auto& set = settings_;
  const Real z = depth;

  // ---- time grid: internal step h = dt / m, period T = N h, damping eps ----
  Real tau = l_ / alpha_;
  for (std::size_t i = 1; i < load_.times().size(); ++i)
    tau = std::min(tau, load_.times()[i] - load_.times()[i - 1]);
  const Real hMax = tau / set.samplesPerTimeScale;
  const Real mReal = std::ceil(dt / hMax * (1 - 1e-12));
  const Real nReal = set.periodFactor * endTime / dt * mReal;
  if (!(nReal < 1 << 24)) throw InputError("dt", "the internal time grid would need more than 2^24 samples");
  const long m = std::max<long>(1, static_cast<long>(mReal));
  const Real h = dt / static_cast<Real>(m);
  const long n = fftFriendly(static_cast<long>(std::ceil(nReal)));
  const Real period = static_cast<Real>(n) * h;
  const Real eps = set.dampingPerPeriod / period;
  const Real bandEnd = kPi / h;
  const long frequencies = n / 2;  // omega_0 .. omega_{N/2 - 1}; the Nyquist term is left out

  // ---- wavenumber cut-off ----
  const Real c2 = (lambda_ + 2 * mu_) / (lambda_ + mu_);  // T_0 = e^{-kz} [c2 / k + z] / (2 mu)
  // The cut-off leaves out g - g_0 ~ (|s| / (c k))^2 g_0: K is a multiple of |s| / c_R, and at
  // least 16 / (the smaller of l and c_R / eps) so that the low frequencies, where |s| ~ eps, also
  // have K >> |s| / c_R and resolve the load's transform.
  const Real kFloor = 16 * std::max(1 / l_, eps / cR_);
  auto surfaceCutoff = [&](Complex s) { return set.cutoffFactor * (std::abs(s) / cR_ + kFloor); };
  const Real kSurfaceMax = surfaceCutoff(Complex(eps, bandEnd));
  auto cutoff = [&](Complex s) {
    if (z == 0) return surfaceCutoff(s);
    // Below the surface the integrand decays like e^{-Re(nu) z}, Re nu >= sqrt(k^2 - |s|^2/beta^2):
    // e^{-36} ~ 2e-16. Shallow receivers, where that would exceed the surface's largest cut-off,
    // use the latter: the strip keeps its quasi-static sum (exact at any depth); the square has no
    // tail below the surface, but there K is the largest and the tail beyond it small (its response
    // at depth 1e-3 and 1e-2 differs from the surface's linearly in z, to 1%).
    return std::min(std::hypot(std::abs(s) / beta_, 36 / z), kSurfaceMax);
  };
  const Real kMax = cutoff(Complex(eps, bandEnd));

  const Medium medium{1 / (alpha_ * alpha_), 1 / (beta_ * beta_), mu_};
  const auto& slopeJumps = load_.slopeJumps();
  const auto& breakTimes = load_.times();

  // Strip: trapezoid nodes k_j = j dk with the s-independent factors Xhat(k_j) cos(k_j x) / pi.
  std::vector<Real> stripFactor, stripStatic;
  Real stripStaticSum = 0;
  Real dk = 0;
  // Square: path nodes, their weights times k A(k) / 4pi^2, and per panel end the cumulative
  // int A dk along the path (for the static tail).
  std::vector<Complex> pathK, pathFactor, panelStatic;
  std::vector<Real> panelEndRe;
  const int panelPoints = 16;

  if (shape_ == SurfaceLoadShape::Strip) {
    // Period L of the images: the strips do not overlap (L > 2l) and the first P wave from an
    // image, at (L - l - |x|) / alpha, arrives after endTime (by a quarter of it plus (l+|x|)/alpha).
    const Real images = 1.25 * alpha_ * endTime + 2 * (l_ + std::abs(x));
    dk = set.wavenumberSpacing * 2 * kPi / images;
    const auto nodes = static_cast<std::size_t>(std::ceil(kMax / dk)) + 1;
    stripFactor.resize(nodes);
    stripStatic.resize(nodes);
    for (std::size_t j = 0; j < nodes; ++j) {
      const Real k = static_cast<Real>(j) * dk;
      stripFactor[j] = 2 * l_ * sinc(Complex(k * l_)).real() * std::cos(k * x) / kPi;
      // g_0 = Xhat cos(kx) T_0 / pi, left out at k = 0 (where it is singular; see the sum below).
      if (j > 0) stripStatic[j] = stripFactor[j] * std::exp(-k * z) * (c2 / k + z) / (2 * mu_);
    }
    // The sum of g_0 over all nodes j >= 1 (to infinity), in closed form: with sin(ka), a = l +- x,
    //   dk sum_j g_0(j dk) = 1/(2 pi mu) sum_a [c2/dk Im Li_2(e^{w_a}) - z Im log(1 - e^{w_a})],
    //   w_a = dk (i a - z).
    for (Real a : {l_ + x, l_ - x}) {
      const Complex w = dk * Complex(-z, a);
      if (std::abs(w) == 0) continue;  // a = 0 at the surface: sin(ka) = 0
      const Real logTerm = z > 0 ? -std::log(1.0 - std::exp(w)).imag() : 0;
      stripStaticSum += (c2 / dk * dilogarithmOfExp(w).imag() + z * logTerm) / (2 * kPi * mu_);
    }
  } else {
    const QuadratureRule rule = gaussLegendre(panelPoints);
    const Real lift = 1 / l_;  // height of the path above the real axis
    const Real nearest = eps / alpha_;                // nearest singularity below the real axis
    const Real fine = set.wavenumberSpacing * 2 * nearest;
    const Real coarse = set.wavenumberSpacing * std::min(2 * (nearest + lift), 6 / (std::sqrt(2.0) * l_ + z));
    Complex sumA = 0;
    auto addSegment = [&](Complex from, Complex to, Real width) {
      const int panels = std::max(1, static_cast<int>(std::ceil(std::abs(to - from) / width)));
      for (int p = 0; p < panels; ++p) {
        const Complex a = from + (to - from) * (static_cast<Real>(p) / panels);
        const Complex b = from + (to - from) * (static_cast<Real>(p + 1) / panels);
        const Complex half = 0.5 * (b - a), mid = 0.5 * (a + b);
        for (int i = 0; i < panelPoints; ++i) {
          const Complex k = mid + half * rule.nodes[static_cast<std::size_t>(i)];
          const Complex w = half * rule.weights[static_cast<std::size_t>(i)];
          const Complex A = squareAngularIntegral(k, l_);
          pathK.push_back(k);
          pathFactor.push_back(w * k * A / (4 * kPi * kPi));
          sumA += w * A;
        }
        panelStatic.push_back(sumA);
        panelEndRe.push_back(b.real());
      }
    };
    const Complex k0 = 0, k1 = lift, k2 = Complex(2 * lift, lift);
    addSegment(k0, k1, fine);
    addSegment(k1, k2, fine);
    addSegment(k2, Complex(std::max(kMax, 2 * lift + coarse), lift), coarse);
  }

  // ---- frequency loop ----
  std::vector<Complex> spectrumU(static_cast<std::size_t>(n / 2 + 1), 0.0), spectrumV(spectrumU.size(), 0.0);
  // Receivers under the load see its plane P wave (half of it exactly below an edge of the strip).
  const Real planeWaveShare = std::abs(x) < l_ ? 1.0 : std::abs(x) == l_ ? 0.5 : 0.0;
  const Real rollStart = (1 - set.taper) * bandEnd;
  const Real staticCentre = 2 * kPi * 8 * l_ * std::log(1 + std::sqrt(2.0));  // int_0^inf A dk
  for (long i = 0; i < frequencies; ++i) {
    const Real omega = 2 * kPi * static_cast<Real>(i) / period;
    const Complex s(eps, omega), s2 = s * s;
    Complex loadTransform = 0;
    for (std::size_t b = 0; b < slopeJumps.size(); ++b)
      if (slopeJumps[b] != 0) loadTransform += slopeJumps[b] * std::exp(-s * breakTimes[b]);
    loadTransform /= s2;
    const Real kCut = cutoff(s);
    Complex sum = 0;
    if (shape_ == SurfaceLoadShape::Strip) {
      // By Poisson summation the trapezoid sum over all j is exactly the problem periodic in x
      // (period 2 pi / dk), whose images arrive after endTime. It is truncated at K = last dk with
      // the quasi-static integrand g_0 subtracted node by node and its image sum over all nodes
      // added in closed form, so what is cut off, g - g_0, decays like |s|^2 / k^2 relative to g_0
      // (the trapezoid's discrete tail, not an integral, is what must be added: for the
      // oscillating sin(ka) the two differ at O(1)).
      const std::size_t last = std::min(stripFactor.size() - 1, static_cast<std::size_t>(std::ceil(kCut / dk)));
      sum = 0.5 * dk * stripFactor[0] * medium.transfer(Complex(0), s2, z) + stripStaticSum;
      for (std::size_t j = 1; j <= last; ++j) {
        const Real k = static_cast<Real>(j) * dk;
        sum += dk * (stripFactor[j] * medium.transfer(Complex(k * k), s2, z) - stripStatic[j]);
      }
    } else {
      std::size_t panel = 0;
      while (panel + 1 < panelEndRe.size() && panelEndRe[panel] < kCut) ++panel;
      const std::size_t last = (panel + 1) * static_cast<std::size_t>(panelPoints);
      for (std::size_t j = 0; j < last; ++j) sum += pathFactor[j] * medium.transfer(pathK[j] * pathK[j], s2, z);
      // Tail beyond the path's end with T -> c2 / (2 mu k) at the surface: (c2/(2 mu 4pi^2)) int A dk,
      // the path integral of the entire function A from its end to infinity = total - path so far.
      if (z == 0) sum += c2 / (2 * mu_) / (4 * kPi * kPi) * (staticCentre - panelStatic[panel]);
    }
    // The plane P wave under the load, p F e^{-s z/alpha} / (rho alpha s), carries the kinks of f
    // (the strongest singularities of the response): subtract it here and add it back exactly in
    // time, so that the band limit does not smear them.
    sum -= planeWaveShare * std::exp(-s * (z / alpha_)) / (rho_ * alpha_ * s);
    Real window = 1;
    if (omega > rollStart) window = 0.5 * (1 + std::cos(kPi * (omega - rollStart) / (bandEnd - rollStart)));
    const Complex u = p_ * loadTransform * sum * window;
    spectrumU[static_cast<std::size_t>(i)] = u;
    spectrumV[static_cast<std::size_t>(i)] = s * u;
  }

  // ---- back to time ----
  Series out;
  const auto samples = static_cast<std::size_t>(std::floor(endTime / dt * (1 + 1e-12))) + 1;
  out.time.resize(samples);
  out.displacement.resize(samples);
  out.velocity.resize(samples);
  InverseTransform transform(n);
  for (int field = 0; field < 2; ++field) {
    const Real* values = transform.run(field == 0 ? spectrumU : spectrumV);
    auto& target = field == 0 ? out.displacement : out.velocity;
    for (std::size_t j = 0; j < samples; ++j) {
      const Real t = static_cast<Real>(j) * dt;
      out.time[j] = t;
      target[j] = std::exp(eps * t) / period * values[j * static_cast<std::size_t>(m)];
      const Real arrival = t - z / alpha_;
      if (planeWaveShare > 0 && arrival > 0) {
        const Real amplitude = planeWaveShare * p_ / (rho_ * alpha_);
        target[j] += field == 0 ? amplitude * load_.superpose(arrival, [](Real r) { return r > 0 ? 0.5 * r * r : 0.0; })
                                : amplitude * load_.value(arrival);
      }
    }
  }
  return out;
}

}  // namespace mfwave
