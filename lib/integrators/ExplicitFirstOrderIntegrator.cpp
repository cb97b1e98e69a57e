#include "integrators/ExplicitFirstOrderIntegrator.hpp"

#include "core/Error.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace mfwave {

void ExplicitFirstOrderIntegrator::initialise(FirstOrderSystem& system, Real t0, const Vector& y0, Real dt) {
  checkInitialState(system, t0, y0, dt);
  system_ = &system;
  y_ = y0;
  time_ = t0;
  steps_ = 0;
  evaluations_ = 0;
  nominalStep_ = dt;
  lastStep_ = dt;
  clockOrigin_ = t0;
  clockStep_ = 0;
  clockSteps_ = 0;
  start();
}

void ExplicitFirstOrderIntegrator::requireInitialised(const char* what) const {
  if (!system_) throw Error(name() + ": " + what + " called before initialise()");
}

void ExplicitFirstOrderIntegrator::takeStep(Real dt, bool landing, Real landOn) {
  advance(dt);
  ++steps_;
  lastStep_ = dt;
  if (landing) {
    time_ = landOn;
    clockStep_ = 0;  // the next step starts a new grid at t
    return;
  }
  if (dt != clockStep_) {
    clockOrigin_ = time_;
    clockStep_ = dt;
    clockSteps_ = 0;
  }
  ++clockSteps_;
  time_ = clockOrigin_ + static_cast<Real>(clockSteps_) * clockStep_;
}

void ExplicitFirstOrderIntegrator::step() {
  requireInitialised("step()");
  takeStep(nextStepSize(nominalStep_), false, 0);
}

void ExplicitFirstOrderIntegrator::advanceTo(Real t) {
  requireInitialised("advanceTo()");
  if (!std::isfinite(t)) throw InputError("end_time", "must be finite");
  const Real roundoff = 1e-14 * std::max(Real(1), std::abs(t));
  if (t < time_ - roundoff) throw InputError("end_time", "lies before the current time " + std::to_string(time_));
  while (t - time_ > roundoff) {
    const Real remaining = t - time_;
    const Real dt = nextStepSize(nominalStep_);
    // A step that reaches t, or falls short of it by less than 1e-9 of a step, becomes the last
    // one, of size t - time() (or dt itself when the two differ by round-off only, so that landing
    // on the step grid computes what step() computes).
    if (dt >= remaining * (1 - 1e-9))
      takeStep(std::abs(dt - remaining) <= 1e-12 * dt ? dt : remaining, true, t);
    else
      takeStep(dt, false, 0);
  }
  time_ = t;  // within round-off already; keep the caller's value exactly
}

void ExplicitFirstOrderIntegrator::saveState(StateArchive& archive) const {
  requireInitialised("saveState()");
  archive.put("y", y_);
  archive.put("clock", std::vector<Real>{time_, static_cast<Real>(steps_), evaluations_, nominalStep_, lastStep_,
                                         clockOrigin_, clockStep_, static_cast<Real>(clockSteps_)});
  StateArchive history = archive.section("history");
  saveHistory(history);
  StateArchive system = archive.section("system");
  system_->saveState(system);
}

void ExplicitFirstOrderIntegrator::restoreState(const StateArchive& archive) {
  requireInitialised("restoreState()");
  archive.get("y", y_);
  const std::vector<Real>& clock = archive.numbers("clock", 8);
  time_ = clock[0];
  steps_ = static_cast<long>(clock[1]);
  evaluations_ = clock[2];
  nominalStep_ = clock[3];
  lastStep_ = clock[4];
  clockOrigin_ = clock[5];
  clockStep_ = clock[6];
  clockSteps_ = static_cast<long>(clock[7]);
  restoreHistory(archive.section("history"));
  system_->restoreState(archive.section("system"));
}

}  // namespace mfwave
