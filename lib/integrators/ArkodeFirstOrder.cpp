#include "integrators/ArkodeFirstOrder.hpp"

#include "core/Error.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

namespace mfwave {

ArkodeFirstOrder::ArkodeFirstOrder(ArkodeOptions options)
    : options_(std::move(options)), arkode_(std::make_unique<ArkodeExplicit>(options_)) {}

void ArkodeFirstOrder::initialise(FirstOrderSystem& system, Real t0, const Vector& y0, Real dt) {
  checkInitialState(system, t0, y0, dt);
  ArkodeOptions options = options_;
  if (options.adaptive) {
    if (!(options.initialStep > 0)) options.initialStep = dt;
  } else {
    options.fixedStep = dt;
  }
  dt_ = options.adaptive ? options.initialStep : dt;
  initialised_ = false;
  arkode_ = std::make_unique<ArkodeExplicit>(options);
  arkode_->initialise(system, t0, y0);
  steps_ = 0;
  initialised_ = true;
}

void ArkodeFirstOrder::requireInitialised(const char* what) const {
  if (!initialised_) throw Error(std::string("arkode: ") + what + " called before initialise()");
}

Real ArkodeFirstOrder::applyRule() {
  if (!hasStepSizeFunction()) return options_.adaptive ? 0 : dt_;
  const Real h = nextStepSize(dt_);
  if (options_.adaptive)
    arkode_->setMaxStep(h);
  else
    arkode_->setFixedStep(h);
  return h;
}

void ArkodeFirstOrder::step() {
  requireInitialised("step()");
  applyRule();
  arkode_->step();
  steps_ = arkode_->statistics().steps;
}

void ArkodeFirstOrder::advanceTo(Real t) {
  requireInitialised("advanceTo()");
  if (!std::isfinite(t)) throw InputError("end_time", "must be finite");
  if (!hasStepSizeFunction()) {
    arkode_->advanceTo(t);  // fixed: whole steps and a shortened last one; adaptive: ARKODE's steps
    steps_ = arkode_->statistics().steps;
    return;
  }
  const Real roundoff = 1e-14 * std::max(Real(1), std::abs(t));
  if (t < time() - roundoff) throw InputError("end_time", "lies before the current time " + std::to_string(time()));
  // With a rule, one step at a time so the rule sees every state. A step that would reach t (or
  // fall short of it by less than 1e-9 of a step) is left to ARKODE's stop time, which shortens
  // it to land on t. In adaptive runs ARKODE may split that remainder further, under the bound.
  while (t - time() > roundoff) {
    const Real h = applyRule();
    const Real remaining = t - time();
    if (h >= remaining * (1 - 1e-9)) {
      // A fixed step a hair short of t would leave a sliver of a step: stretch it to reach t.
      if (!options_.adaptive && h < remaining) arkode_->setFixedStep(remaining);
      arkode_->advanceTo(t);
      break;
    }
    arkode_->step();
    steps_ = arkode_->statistics().steps;
  }
  steps_ = arkode_->statistics().steps;
}

Real ArkodeFirstOrder::time() const { return arkode_->time(); }
const Vector& ArkodeFirstOrder::solution() const { return arkode_->state(); }

Real ArkodeFirstOrder::stepSize() const {
  const Real last = arkode_->isInitialised() ? arkode_->lastStepSize() : 0;
  return last > 0 ? last : dt_;
}

double ArkodeFirstOrder::rhsEvaluations() const {
  return static_cast<double>(arkode_->isInitialised() ? arkode_->statistics().rhsEvaluations : 0);
}

void ArkodeFirstOrder::saveState(StateArchive& archive) const {
  requireInitialised("saveState()");
  arkode_->saveState(archive);
}

void ArkodeFirstOrder::restoreState(const StateArchive& archive) {
  requireInitialised("restoreState()");
  arkode_->restoreState(archive);
  steps_ = arkode_->statistics().steps;
}

}  // namespace mfwave
