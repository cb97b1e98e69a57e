#include "integrators/FixedStepSecondOrderIntegrator.hpp"

#include "core/Error.hpp"
#include "systems/ParallelVector.hpp"

namespace mfwave {

void FixedStepSecondOrderIntegrator::bind(SecondOrderSystem& system, Real t0, const Vector& u0, const Vector& v0,
                                          Real dt) {
  checkInitialState(system, t0, u0, v0, dt);
  system_ = &system;
  t0_ = t0;
  dt_ = dt;
  time_ = t0;
  steps_ = 0;
  u_ = u0;
  v_ = v0;
  a_.resize(u0.size());
}

void FixedStepSecondOrderIntegrator::closeHalfStep(const Vector& vHalf, Vector& vPredict) {
  if (system_->dependsOnVelocity()) {
    assignSum(vPredict, vHalf, 0.5 * dt_, a_);
    system_->acceleration(time_, u_, vPredict, a_);
  } else {
    system_->acceleration(time_, u_, vHalf, a_);  // v is ignored by the system
  }
  assignSum(v_, vHalf, 0.5 * dt_, a_);
}

void FixedStepSecondOrderIntegrator::requireInitialised() const {
  if (!system_) throw Error(name() + ": step() called before initialise()");
}

}  // namespace mfwave
