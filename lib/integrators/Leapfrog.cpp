#include "integrators/Leapfrog.hpp"

namespace mfwave {

void Leapfrog::initialise(SecondOrderSystem& system, Real t0, const Vector& u0, const Vector& v0, Real dt) {
  bind(system, t0, u0, v0, dt);
  vHalf_.resize(u0.size());
  system.acceleration(t0, u_, v_, a_);
  if (system.dependsOnVelocity()) vPredict_.resize(u0.size());
}

void Leapfrog::step() {
  requireInitialised();
  vHalf_ = v_ + 0.5 * dt_ * a_;   // kick
  u_.noalias() += dt_ * vHalf_;   // drift
  advanceClock();
  closeHalfStep(vHalf_, vPredict_);  // a_{n+1} and the closing kick
}

}  // namespace mfwave
