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

void FixedStepSecondOrderIntegrator::saveState(StateArchive& archive) const {
  requireInitialised();
  archive.putScalar("t0", t0_);
  archive.putScalar("dt", dt_);
  archive.putScalar("time", time_);
  archive.putScalar("steps", static_cast<Real>(steps_));
  archive.put("u", u_);
  archive.put("v", v_);
  archive.put("a", a_);
  StateArchive history = archive.section("history");
  saveHistory(history);
  StateArchive system = archive.section("system");
  system_->saveState(system);
}

void FixedStepSecondOrderIntegrator::restoreState(const StateArchive& archive) {
  requireInitialised();
  if (archive.scalar("dt") != dt_ || archive.scalar("t0") != t0_)
    throw InputError("--restart", name() + ": the checkpoint was taken with the step " +
                                      std::to_string(archive.scalar("dt")) + " from t0 = " +
                                      std::to_string(archive.scalar("t0")) + ", this run steps " +
                                      std::to_string(dt_) + " from " + std::to_string(t0_));
  time_ = archive.scalar("time");
  steps_ = archive.integer("steps");
  archive.get("u", u_);
  archive.get("v", v_);
  archive.get("a", a_);
  restoreHistory(archive.section("history"));
  system_->restoreState(archive.section("system"));
}

void FixedStepSecondOrderIntegrator::requireInitialised() const {
  if (!system_) throw Error(name() + ": step() called before initialise()");
}

}  // namespace mfwave
