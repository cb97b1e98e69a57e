#include "integrators/CentralDifference.hpp"

namespace mfwave {

void CentralDifference::initialise(SecondOrderSystem& system, Real t0, const Vector& u0, const Vector& v0,
                                   Real dt) {
  bind(system, t0, u0, v0, dt);
  system.acceleration(t0, u_, v_, a_);  // v0 is exact here: no predictor needed for a_0
  // Half a step back, so that the first full step is the Taylor start u_1 = u_0 + dt v_0 + dt^2/2 a_0.
  vHalf_ = v_ - 0.5 * dt_ * a_;
  if (system.dependsOnVelocity()) vPredict_.resize(u0.size());
}

void CentralDifference::step() {
  requireInitialised();
  // Ding-Long-Wu eq. 23 in staggered form.
  vHalf_.noalias() += dt_ * a_;  // v_{n+1/2} = v_{n-1/2} + dt a_n
  u_.noalias() += dt_ * vHalf_;  // u_{n+1} = u_n + dt v_{n+1/2}
  advanceClock();
  closeHalfStep(vHalf_, vPredict_);  // a_{n+1}, and the synchronous v_{n+1} that is reported
}

}  // namespace mfwave
