#include "analytic/LambSquareLoad.hpp"

#include "analytic/PekerisPointLoad.hpp"
#include "core/Error.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <mutex>
#include <utility>

namespace mfwave {

namespace {

using Rule = std::pair<std::vector<Real>, std::vector<Real>>;  // nodes, weights on [0, 1]

// Gauss-Legendre rule on [0, 1] by Newton iteration on P_n (Golub-Welsch-free, n <= 200).
Rule makeRule(int n) {
  std::vector<Real> x(static_cast<std::size_t>(n)), w(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    Real z = std::cos(kPi * (i + 0.75) / (n + 0.5));
    Real dp = 0;
    for (int it = 0; it < 100; ++it) {
      Real p0 = 1, p1 = z;
      for (int k = 2; k <= n; ++k) {
        const Real p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (z * p1 - p0) / (z * z - 1);
      const Real dz = p1 / dp;
      z -= dz;
      if (std::abs(dz) < 1e-16) break;
    }
    x[static_cast<std::size_t>(i)] = 0.5 * (1 - z);
    w[static_cast<std::size_t>(i)] = 1 / ((1 - z * z) * dp * dp);  // (2 / ((1-z^2) P'^2)) / 2
  }
  return {x, w};
}

const Rule& rule(int n) {
  static std::mutex mutex;
  static std::map<int, Rule> cache;
  std::lock_guard<std::mutex> lock(mutex);
  auto it = cache.find(n);
  if (it == cache.end()) it = cache.emplace(n, makeRule(n)).first;
  return it->second;
}

}  // namespace

LambSquareLoad::LambSquareLoad(Real shearModulus, Real shearSpeed, Real halfWidth,
                               std::vector<Real> times, std::vector<Real> values, Real pressure)
    : mu_(shearModulus), cs_(shearSpeed), l_(halfWidth), p_(pressure),
      times_(std::move(times)), values_(std::move(values)) {
  if (!(mu_ > 0) || !std::isfinite(mu_)) throw InputError("shear_modulus", "must be positive");
  if (!(cs_ > 0) || !std::isfinite(cs_)) throw InputError("shear_speed", "must be positive");
  if (!(l_ > 0) || !std::isfinite(l_)) throw InputError("half_width", "must be positive");
  if (!std::isfinite(p_)) throw InputError("pressure", "must be finite");
  if (times_.size() < 2 || times_.size() != values_.size())
    throw InputError("times", "need at least 2 breakpoints and as many values as times");
  for (std::size_t i = 0; i < times_.size(); ++i) {
    if (!std::isfinite(times_[i]) || !std::isfinite(values_[i]))
      throw InputError("times", "breakpoints must be finite");
    if (i > 0 && !(times_[i] > times_[i - 1]))
      throw InputError("times", "must be strictly increasing");
  }
  if (values_.front() != 0)
    throw InputError("values", "the load must start from 0 (a jump would give infinite velocity)");
  // f(t) = sum_k ds_k (t - t_k)_+ : slope changes at each breakpoint (slope 0 before and after).
  Real previous = 0;
  for (std::size_t i = 0; i < times_.size(); ++i) {
    const Real slope = i + 1 < times_.size()
                           ? (values_[i + 1] - values_[i]) / (times_[i + 1] - times_[i])
                           : 0;
    slopeJumps_.push_back(slope - previous);
    previous = slope;
  }
}

LambSquareLoad LambSquareLoad::dingLongWu() {
  return LambSquareLoad(1, 1, 0.5, {0, 1, 2}, {0, 1, 0}, 1);
}

void LambSquareLoad::setQuadraturePoints(int points) {
  if (points < 2 || points > 200) throw InputError("quadrature_points", "must be in [2, 200]");
  points_ = points;
}

Real LambSquareLoad::loadHistory(Real t) const {
  if (t <= times_.front()) return values_.front();
  if (t >= times_.back()) return values_.back();
  const auto i = static_cast<std::size_t>(
      std::upper_bound(times_.begin(), times_.end(), t) - times_.begin() - 1);
  const Real s = (t - times_[i]) / (times_[i + 1] - times_[i]);
  return values_[i] + s * (values_[i + 1] - values_[i]);
}

// p / (pi mu) * sum over the signed triangles (receiver, corner k, corner k+1) of
// int dtheta of the closed-form radial integral (see the header).
Real LambSquareLoad::integrateSquare(Real x, Real y, Real t, bool ramp) const {
  if (!(t > 0)) return 0;
  using P = PekerisPointLoad;
  const Real c = cs_;
  // Exactly zero before the P wave from the nearest loaded point (the constant c t H(inf) parts
  // of the four triangles cancel only to rounding outside the square).
  const Real gap = std::hypot(std::max<Real>(std::abs(x) - l_, 0), std::max<Real>(std::abs(y) - l_, 0));
  if (gap >= c * P::kSqrt3 * t) return 0;
  const Real hInf = P::shapeOverTauSquaredIntegralAtInfinity();
  // Radial integrals from the receiver to distance R at time t.
  auto radial = [&](Real R) -> Real {
    const Real tau = c * t / R;
    if (!ramp) {
      // c t [H(inf) - H(tau)]; exact 3 R / 8 once the Rayleigh wave has passed (no cancellation).
      if (tau > P::kRayleighTau) return 0.375 * R;
      return c * t * (hInf - P::shapeOverTauSquaredIntegral(tau));
    }
    Real k = 0;
    if (tau > P::kRayleighTau)
      k = 0.375 * tau + 0.5 * (P::shapeIntegral(P::kRayleighTau) - 0.375 * P::kRayleighTau);
    else
      k = 0.5 * tau * tau * (hInf - P::shapeOverTauSquaredIntegral(tau)) + 0.5 * P::shapeIntegral(tau);
    return R * R / c * k;
  };
  const Rule& gl = rule(points_);
  const std::array<Real, 4> cx = {l_, -l_, -l_, l_}, cy = {l_, l_, -l_, -l_};
  const std::array<Real, 3> radii = {c * t * P::kSqrt3, c * t, c * t / P::kRayleighTau};
  Real total = 0;
  for (int k = 0; k < 4; ++k) {
    const int k1 = (k + 1) % 4;
    const Real ax = cx[static_cast<std::size_t>(k)] - x, ay = cy[static_cast<std::size_t>(k)] - y;
    const Real bx = cx[static_cast<std::size_t>(k1)] - x, by = cy[static_cast<std::size_t>(k1)] - y;
    const Real ex = bx - ax, ey = by - ay, len = std::hypot(ex, ey);
    // Distance d from the receiver to the edge line and the unit normal n towards it.
    Real nx = ey / len, ny = -ex / len;
    Real d = ax * nx + ay * ny;
    if (std::abs(d) <= 1e-14 * l_) continue;  // receiver on the edge line: zero-area triangle
    if (d < 0) {
      nx = -nx;
      ny = -ny;
      d = -d;
    }
    // The corners CCW-ordered, so the triangle counts with the sign of its oriented area.
    const Real sign = ax * by - ay * bx > 0 ? 1 : -1;
    // Ray angles phi measured from n: the ray meets the edge line at R = d / cos(phi).
    auto angle = [&](Real px, Real py) { return std::atan2(-px * ny + py * nx, px * nx + py * ny); };
    Real a0 = angle(ax, ay), a1 = angle(bx, by);
    if (a0 > a1) std::swap(a0, a1);
    // Split points: the foot of the perpendicular and where R(phi) = d / cos(phi) hits a front.
    std::vector<Real> cuts = {a0, a1};
    if (a0 < 0 && 0 < a1) cuts.push_back(0);
    for (Real rr : radii) {
      if (rr > d) {
        const Real phi = std::acos(d / rr);
        if (a0 < phi && phi < a1) cuts.push_back(phi);
        if (a0 < -phi && -phi < a1) cuts.push_back(-phi);
      }
    }
    std::sort(cuts.begin(), cuts.end());
    Real edgeSum = 0;
    for (std::size_t j = 0; j + 1 < cuts.size(); ++j) {
      const Real lo = cuts[j], h = cuts[j + 1] - lo;
      if (!(h > 0)) continue;
      Real s = 0;
      for (std::size_t q = 0; q < gl.first.size(); ++q) {
        const Real u = gl.first[q];
        // Smoothstep map phi = lo + h (3u^2 - 2u^3): flattens sqrt endpoint behaviour.
        const Real phi = lo + h * u * u * (3 - 2 * u);
        const Real jac = h * 6 * u * (1 - u);
        s += gl.second[q] * jac * radial(d / std::cos(phi));
      }
      edgeSum += s;
    }
    total += sign * edgeSum;
  }
  return p_ / (kPi * mu_) * total;
}

Real LambSquareLoad::stepDisplacement(Real x, Real y, Real t) const {
  return integrateSquare(x, y, t, false);
}

Real LambSquareLoad::rampDisplacement(Real x, Real y, Real t) const {
  return integrateSquare(x, y, t, true);
}

Real LambSquareLoad::displacement(Real x, Real y, Real t) const {
  Real u = 0;
  for (std::size_t k = 0; k < times_.size(); ++k)
    if (slopeJumps_[k] != 0) u += slopeJumps_[k] * rampDisplacement(x, y, t - times_[k]);
  return u;
}

Real LambSquareLoad::velocity(Real x, Real y, Real t) const {
  Real v = 0;
  for (std::size_t k = 0; k < times_.size(); ++k)
    if (slopeJumps_[k] != 0) v += slopeJumps_[k] * stepDisplacement(x, y, t - times_[k]);
  return v;
}

}  // namespace mfwave
