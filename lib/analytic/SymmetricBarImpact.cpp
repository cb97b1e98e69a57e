#include "analytic/SymmetricBarImpact.hpp"

#include "core/Error.hpp"

#include <cmath>

namespace mfwave {

namespace {
void requirePositive(Real value, const char* key) {
  if (!(value > 0) || !std::isfinite(value)) throw InputError(key, "must be positive and finite");
}
}  // namespace

SymmetricBarImpact::SymmetricBarImpact(Real length, Real waveSpeed, Real density, Real impactSpeed)
    : length_(length), c_(waveSpeed), rho_(density), v0_(impactSpeed) {
  requirePositive(length, "length");
  requirePositive(waveSpeed, "wave_speed");
  requirePositive(density, "density");
  if (!std::isfinite(impactSpeed)) throw InputError("impact_speed", "must be finite");
}

void SymmetricBarImpact::checkTime(Real t) const {
  if (!(t >= 0) || t > validUntil() * (1 + 1e-12))
    throw InputError("time", "the solution holds for 0 <= t <= L / c = " + std::to_string(validUntil()) +
                                 " (before the fronts reach the free ends)");
}

Real SymmetricBarImpact::velocity(Real x, Real t) const {
  checkTime(t);
  const Real outside = x < 0 ? v0_ : (x > 0 ? -v0_ : 0);
  const Real distance = std::abs(x) - c_ * t;
  if (distance > 0) return outside;
  if (distance < 0) return 0;
  return outside / 2;
}

Real SymmetricBarImpact::stress(Real x, Real t) const {
  checkTime(t);
  const Real distance = std::abs(x) - c_ * t;
  if (distance > 0) return 0;
  if (distance < 0) return interfaceStress();
  return interfaceStress() / 2;
}

}  // namespace mfwave
