#include "analytic/FixedFreeBarImpact.hpp"

#include "core/Error.hpp"

#include <cmath>

namespace mfwave {

FixedFreeBarImpact::FixedFreeBarImpact(Real length, Real waveSpeed, Real initialVelocity)
    : length_(length), c_(waveSpeed), v0_(initialVelocity) {
  if (!(length > 0) || !std::isfinite(length)) throw InputError("length", "must be positive");
  if (!(waveSpeed > 0) || !std::isfinite(waveSpeed)) throw InputError("wave_speed", "must be positive");
  if (!std::isfinite(initialVelocity)) throw InputError("initial_velocity", "must be finite");
}

Real FixedFreeBarImpact::squareWave(Real y) const {
  const Real p = 4 * length_;
  Real r = std::fmod(y, p);
  if (r < 0) r += p;
  const Real tol = 1e-12 * p;
  if (std::abs(r) < tol || std::abs(r - 2 * length_) < tol || std::abs(r - p) < tol) return 0;
  return r < 2 * length_ ? 1 : -1;
}

Real FixedFreeBarImpact::triangleWave(Real y) const {
  const Real p = 4 * length_;
  Real r = std::fmod(y, p);
  if (r < 0) r += p;
  return r <= 2 * length_ ? r : p - r;
}

Real FixedFreeBarImpact::displacement(Real x, Real t) const {
  return v0_ / (2 * c_) * (triangleWave(x + c_ * t) - triangleWave(x - c_ * t));
}

Real FixedFreeBarImpact::velocity(Real x, Real t) const {
  return 0.5 * v0_ * (squareWave(x - c_ * t) + squareWave(x + c_ * t));
}

Real FixedFreeBarImpact::strain(Real x, Real t) const {
  return v0_ / (2 * c_) * (squareWave(x + c_ * t) - squareWave(x - c_ * t));
}

}  // namespace mfwave
