#pragma once
// Two identical elastic bars meeting at x = 0: the bar on [-L, 0] moves with +v0, the bar on
// [0, L] with -v0, both unstressed at t = 0. The impact sends a compression front into each bar at
// the wave speed c; behind the fronts the material is at rest and carries the stress -rho c v0
// (the characteristic relation d sigma = -rho c dv across a right-going front, +rho c dv across a
// left-going one, with dv = -v0 on the left):
//
//   |x| < c t:   v = 0,                 sigma = -rho c v0
//   |x| > c t:   v = +v0 (x < 0), -v0 (x > 0),   sigma = 0
//
// valid until the fronts reach the free ends (t < L / c). c is the speed of the waves the model
// carries: c_p for uniaxial strain (the 1-D updated-Lagrangian SPH), sqrt(E / rho) for a thin bar.

#include "core/Types.hpp"

namespace mfwave {

class SymmetricBarImpact {
 public:
  // Throws InputError naming "length", "wave_speed" or "density" unless positive and finite, and
  // "impact_speed" unless finite.
  SymmetricBarImpact(Real length, Real waveSpeed, Real density, Real impactSpeed);

  // At a front (|x| = c t) the mean of the two sides. Throws InputError("time") for t outside
  // [0, L / c].
  Real velocity(Real x, Real t) const;
  Real stress(Real x, Real t) const;
  Real frontPosition(Real t) const { return c_ * t; }  // the right-going front; the other is at -c t
  Real interfaceStress() const { return -rho_ * c_ * v0_; }
  Real validUntil() const { return length_ / c_; }

 private:
  void checkTime(Real t) const;
  Real length_, c_, rho_, v0_;
};

}  // namespace mfwave
