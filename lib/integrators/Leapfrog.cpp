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
  if (system_->dependsOnVelocity()) {
    // v_{n+1} is not known before a_{n+1}: predict it to O(dt^2) with the old acceleration.
    vPredict_ = vHalf_ + 0.5 * dt_ * a_;
    system_->acceleration(time_, u_, vPredict_, a_);
  } else {
    system_->acceleration(time_, u_, vHalf_, a_);  // v is ignored by the system
  }
  v_ = vHalf_ + 0.5 * dt_ * a_;   // kick
}

}  // namespace mfwave
