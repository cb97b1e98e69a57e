#include "analytic/LambSquareLoad.hpp"

#include "analytic/PekerisPointLoad.hpp"
#include "analytic/SmoothstepQuadrature.hpp"
#include "core/Error.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace mfwave {

LambSquareLoad::LambSquareLoad(Real shearModulus, Real shearSpeed, Real halfWidth,
                               std::vector<Real> times, std::vector<Real> values, Real pressure)
    : mu_(shearModulus), cs_(shearSpeed), l_(halfWidth), p_(pressure),
      load_(std::move(times), std::move(values)), rule_(gaussLegendre(24)) {
  if (!(mu_ > 0) || !std::isfinite(mu_)) throw InputError("shear_modulus", "must be positive");
  if (!(cs_ > 0) || !std::isfinite(cs_)) throw InputError("shear_speed", "must be positive");
  if (!(l_ > 0) || !std::isfinite(l_)) throw InputError("half_width", "must be positive");
  if (!std::isfinite(p_)) throw InputError("pressure", "must be finite");
}

LambSquareLoad LambSquareLoad::dingLongWu() {
  return LambSquareLoad(1, 1, 0.5, {0, 1, 2}, {0, 1, 0}, 1);
}

void LambSquareLoad::setQuadraturePoints(int points) {
  if (points < 2 || points > 200) throw InputError("quadrature_points", "must be in [2, 200]");
  rule_ = gaussLegendre(points);
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
    // Each piece mapped by a smoothstep: flattens the sqrt behaviour at the fronts' crossings.
    const Real edgeSum =
        integrateSmoothstepPieces(cuts, rule_, [&](Real phi) { return radial(d / std::cos(phi)); });
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
  return load_.superpose(t, [&](Real tau) { return rampDisplacement(x, y, tau); });
}

Real LambSquareLoad::velocity(Real x, Real y, Real t) const {
  return load_.superpose(t, [&](Real tau) { return stepDisplacement(x, y, tau); });
}

}  // namespace mfwave
