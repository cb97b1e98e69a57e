#include "analytic/LambStripLoad.hpp"

#include "analytic/RayleighWave.hpp"
#include "analytic/SmoothstepQuadrature.hpp"
#include "core/Error.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <utility>

namespace mfwave {

namespace {

using Complex = std::complex<Real>;

// gamma_c(q) = sqrt(1/c^2 - q^2) continued from Re gamma > 0 on the imaginary q axis (real
// wavenumbers) into Re q > 0, approached from Im q >= 0 (every Cagniard path here lies there): on
// the real axis beyond 1/c it is the lower side of the cut, -i sqrt(q^2 - 1/c^2).
Complex verticalSlowness(Complex q, Real inverseSpeedSquared) {
  const Complex w = inverseSpeedSquared - q * q;
  if (q.imag() == 0) {
    if (w.real() >= 0) return {std::sqrt(w.real()), 0};
    return {0, -std::sqrt(-w.real())};
  }
  return std::sqrt(w);
}

// R(q) = (1/c_s^2 - 2 q^2)^2 + 4 q^2 gamma_p gamma_s (header), inverseShearSquared = 1/c_s^2.
Complex rayleighFunction(Complex q, Complex gp, Complex gs, Real inverseShearSquared) {
  const Complex a = inverseShearSquared - 2.0 * q * q;
  return a * a + 4.0 * q * q * gp * gs;
}

// (t - t')^n / n! for n = 1, 2: the step (n = 1) and ramp (n = 2) responses from the impulse kernel.
Real weight(Real t, Real tPrime, int power) {
  const Real d = t - tPrime;
  return power == 1 ? d : 0.5 * d * d;
}

// Breakpoints a, a + d, a + 3d, a + 7d, ... up to b (widths doubling): the kernels vary on the
// scale of the front's time near it and on the scale of t long after it.
void appendGraded(std::vector<Real>& cuts, Real a, Real b, Real first) {
  Real width = first;
  for (Real c = a + width; c < b; c += width, width *= 2) cuts.push_back(c);
}

}  // namespace

LambStripLoad::LambStripLoad(Real lambda, Real mu, Real rho, Real halfWidth, std::vector<Real> times,
                             std::vector<Real> values, Real pressure)
    : mu_(mu), l_(halfWidth), p_(pressure), load_(std::move(times), std::move(values)),
      rule_(gaussLegendre(24)) {
  if (!(lambda >= 0) || !std::isfinite(lambda)) throw InputError("lambda", "must be >= 0 and finite");
  if (!(mu > 0) || !std::isfinite(mu)) throw InputError("shear_modulus", "must be positive");
  if (!(rho > 0) || !std::isfinite(rho)) throw InputError("density", "must be positive");
  if (!(halfWidth > 0) || !std::isfinite(halfWidth)) throw InputError("half_width", "must be positive");
  if (!std::isfinite(pressure)) throw InputError("pressure", "must be finite");
  cp_ = std::sqrt((lambda + 2 * mu) / rho);
  cs_ = std::sqrt(mu / rho);
  // Beyond 1/c_s, where the surface kernel has its pole, R is real but near its root a difference
  // of two nearly equal terms. Rationalised, R = N(x) / (a^2 + 4 x s_p s_s) with x = q^2,
  // a = 1/c_s^2 - 2x, s_c = sqrt(x - 1/c^2), and N(x) = a^4 - 16 x^2 (x - 1/c_p^2)(x - 1/c_s^2) the
  // Rayleigh cubic: N = c3 x^3 + c2 x^2 + c1 x + c0. Its root x_R = 1 / c_R^2 is known to rounding,
  // and N = (x - x_R)(d2 x^2 + d1 x + d0) by synthetic division: no cancellation left near the pole.
  const Real a2 = 1 / (cp_ * cp_), b2 = 1 / (cs_ * cs_);
  const Real c3 = 16 * (a2 - b2), c2 = 24 * b2 * b2 - 16 * a2 * b2, c1 = -8 * b2 * b2 * b2;
  const Real cR = mfwave::rayleighWaveSpeed(cp_, cs_);
  rayleighSlowness_ = 1 / cR;
  rayleighX_ = rayleighSlowness_ * rayleighSlowness_;
  quotient_[0] = c3;
  quotient_[1] = c2 + rayleighX_ * quotient_[0];
  quotient_[2] = c1 + rayleighX_ * quotient_[1];
}

// The surface kernel beyond the S arrival times (t - t_R): -2 b2 s_p (a^2 + 4 x s_p s_s) /
// (q (q + q_R) Q(x)), smooth through the Rayleigh arrival t_R = xi q_R (k = g / (t - t_R)).
Real LambStripLoad::surfacePoleNumerator(Real q) const {
  const Real a2 = 1 / (cp_ * cp_), b2 = 1 / (cs_ * cs_), x = q * q;
  const Real sp = std::sqrt(std::max<Real>(x - a2, 0)), ss = std::sqrt(std::max<Real>(x - b2, 0));
  const Real a = b2 - 2 * x;
  const Real Q = (quotient_[0] * x + quotient_[1]) * x + quotient_[2];
  return -2 * b2 * sp * (a * a + 4 * x * sp * ss) / (q * (q + rayleighSlowness_) * Q);
}

LambStripLoad LambStripLoad::dingLongWu() {
  return LambStripLoad(1, 1, 1, 0.5, {0, 1, 2}, {0, 1, 0}, 1);
}

void LambStripLoad::setQuadraturePoints(int points) {
  if (points < 2 || points > 200) throw InputError("quadrature_points", "must be in [2, 200]");
  rule_ = gaussLegendre(points);
}

// The surface kernel k(t) = -(2 / xi) s_p Re[1 / R(q)] / (c_s^2 q), q = t / xi (header), zero
// before the P arrival; from xi / c_s on R is real and the Rayleigh pole is taken as a principal
// value by subtracting it.
Real LambStripLoad::halfPlaneSurface(Real xi, Real t, int power) const {
  const Real a2 = 1 / (cp_ * cp_), b2 = 1 / (cs_ * cs_);
  const Real tP = xi / cp_, tS = xi / cs_, tR = xi * rayleighSlowness_;
  const QuadratureRule& rule = rule_;
  // Before the S arrival R is complex (gamma_s real): no pole.
  auto kernel = [&](Real tPrime) {
    const Complex q(tPrime / xi, 0);
    const Complex gp = verticalSlowness(q, a2), gs = verticalSlowness(q, b2);  // gp = -i s_p here
    const Complex R = rayleighFunction(q, gp, gs, b2);
    return -(2 / xi) * (-gp.imag()) * (1.0 / R).real() * b2 / q.real();
  };
  // The plane P wave of the strip's pole at q = 0 reaches the surface at once.
  Real total = -(kPi * cs_ * cs_ / cp_) * weight(t, 0, power);
  if (t <= tP) return total;
  total += integrateSmoothstepPieces({tP, std::min(t, tS)}, rule,
                                     [&](Real s) { return weight(t, s, power) * kernel(s); });
  if (t <= tS) return total;
  // k = g / (t' - t_R): int w k = int [w g - w(t_R) g(t_R)] / (t' - t_R) + w(t_R) g(t_R) ln|...|.
  const Real wR = weight(t, tR, power), A = surfacePoleNumerator(rayleighSlowness_);
  std::vector<Real> cuts = {tS, t};
  if (t > tR) {
    cuts.push_back(tR);
    appendGraded(cuts, tR, t, 0.25 * (tR - tS));
  }
  total += integrateSmoothstepPieces(cuts, rule, [&](Real s) {
    return (weight(t, s, power) * surfacePoleNumerator(s / xi) - wR * A) / (s - tR);
  });
  if (wR != 0) total += wR * A * std::log(std::abs((t - tR) / (tS - tR)));
  return total;
}

// Inside (z > 0): the P and S terms on their own Cagniard paths (header), each integrated from its
// ray arrival (the S term from the head wave's when there is one), plus the plane P wave.
Real LambStripLoad::halfPlaneInterior(Real xi, Real z, Real t, int power) const {
  const Real a2 = 1 / (cp_ * cp_), b2 = 1 / (cs_ * cs_);
  const Real r2 = xi * xi + z * z, r = std::sqrt(r2);
  const QuadratureRule& rule = rule_;
  Real total = 0;
  if (t > z / cp_) total -= (kPi * cs_ * cs_ / cp_) * weight(t, z / cp_, power);
  // 2 Im[G(q) dq/dt] for the P (shear = false) or S term at a point of its path.
  auto term = [&](Complex q, Complex dq, bool shear) {
    const Complex gp = verticalSlowness(q, a2), gs = verticalSlowness(q, b2);
    const Complex R = rayleighFunction(q, gp, gs, b2);
    const Complex G = shear ? 2.0 * q * gp / R : gp * (b2 - 2.0 * q * q) / (q * R);
    return 2 * (G * dq).imag();
  };
  // The hyperbola q = (xi t + i z sqrt(t^2 - (r/c)^2)) / r^2 for t > r / c.
  auto hyperbola = [&](Real tPrime, Real c, bool shear) {
    const Real root = std::sqrt(std::max<Real>(tPrime * tPrime - r2 / (c * c), 0));
    const Complex q(xi * tPrime / r2, z * root / r2), dq(xi / r2, z * tPrime / (root * r2));
    return term(q, dq, shear);
  };
  // Where the path passes nearest the Rayleigh pole (Re q = q_R): a peak of width about z when the
  // receiver is shallow; graded breakpoints about it resolve it.
  const Real tNear = r2 * rayleighSlowness_ / xi;
  auto addNearPole = [&](std::vector<Real>& cuts, Real lo, Real hi) {
    if (z >= 0.5 * xi) return;
    for (Real d = z; d < hi - lo; d *= 2)
      for (Real c : {tNear - d, tNear + d})
        if (lo < c && c < hi) cuts.push_back(c);
    if (lo < tNear && tNear < hi) cuts.push_back(tNear);
  };
  for (const bool shear : {false, true}) {
    const Real c = shear ? cs_ : cp_, front = r / c;
    if (shear && xi / r > cs_ / cp_) {
      // Head wave: the real segment 1/c_p < q < xi / (c_s r) before the S front, where gamma_p is
      // on its cut: q = (xi t - z sqrt((r/c_s)^2 - t^2)) / r^2.
      const Real tHead = xi / cp_ + z * std::sqrt(b2 - a2);
      const Real hi = std::min(t, front);
      if (t > tHead)
        total += integrateSmoothstepPieces({tHead, hi}, rule, [&](Real s) {
          const Real root = std::sqrt(std::max<Real>(r2 / (cs_ * cs_) - s * s, 0));
          const Real q = (xi * s - z * root) / r2, dq = (xi + z * s / root) / r2;
          return weight(t, s, power) * term(Complex(q, 0), Complex(dq, 0), true);
        });
    }
    if (t <= front) continue;
    std::vector<Real> cuts = {front, t};
    appendGraded(cuts, front, t, 0.1 * front);
    addNearPole(cuts, front, t);
    total += integrateSmoothstepPieces(cuts, rule,
                             [&](Real s) { return weight(t, s, power) * hyperbola(s, c, shear); });
  }
  return total;
}

Real LambStripLoad::halfPlane(Real xi, Real z, Real t, int power) const {
  if (xi == 0 || !(t > 0)) return 0;  // J is odd in xi: its principal value at 0 vanishes
  const Real sign = xi > 0 ? 1 : -1;
  return sign * (z == 0 ? halfPlaneSurface(std::abs(xi), t, power)
                        : halfPlaneInterior(std::abs(xi), z, t, power));
}

Real LambStripLoad::response(Real x, Real z, Real t, int power) const {
  if (!(z >= 0) || !std::isfinite(z)) throw InputError("depth", "must be >= 0 and finite");
  if (!std::isfinite(x)) throw InputError("x", "must be finite");
  if (!(t > 0)) return 0;
  return p_ / (2 * kPi * mu_) * (halfPlane(x - l_, z, t, power) - halfPlane(x + l_, z, t, power));
}

Real LambStripLoad::stepDisplacement(Real x, Real depth, Real t) const { return response(x, depth, t, 1); }

Real LambStripLoad::rampDisplacement(Real x, Real depth, Real t) const { return response(x, depth, t, 2); }

Real LambStripLoad::displacement(Real x, Real depth, Real t) const {
  return load_.superpose(t, [&](Real tau) { return rampDisplacement(x, depth, tau); });
}

Real LambStripLoad::velocity(Real x, Real depth, Real t) const {
  return load_.superpose(t, [&](Real tau) { return stepDisplacement(x, depth, tau); });
}

}  // namespace mfwave
