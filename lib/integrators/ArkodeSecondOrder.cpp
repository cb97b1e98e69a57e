#include "integrators/ArkodeSecondOrder.hpp"

#include "core/Error.hpp"

#include <utility>

namespace mfwave {

ArkodeSecondOrder::ArkodeSecondOrder(ArkodeOptions options)
    : options_(std::move(options)), arkode_(std::make_unique<ArkodeExplicit>(options_)) {}

void ArkodeSecondOrder::initialise(SecondOrderSystem& system, Real t0, const Vector& u0, const Vector& v0,
                                   Real dt) {
  checkInitialState(system, t0, u0, v0, dt);
  ArkodeOptions options = options_;
  if (options.adaptive) {
    if (!(options.initialStep > 0)) options.initialStep = dt;
  } else {
    options.fixedStep = dt;
  }
  dt_ = options.adaptive ? options.initialStep : dt;
  // The adapter holds a reference to the system, the integrator one to the adapter: rebuild both.
  arkode_.reset();
  firstOrder_ = std::make_unique<SecondOrderAsFirstOrder>(system);
  arkode_ = std::make_unique<ArkodeExplicit>(options);
  arkode_->initialise(*firstOrder_, t0, firstOrder_->pack(u0, v0));
  steps_ = 0;
  syncState();
}

void ArkodeSecondOrder::step() {
  if (!firstOrder_) throw Error("arkode: step() called before initialise()");
  arkode_->step();
  syncState();
}

void ArkodeSecondOrder::advanceTo(Real t) {
  if (!firstOrder_) throw Error("arkode: advanceTo() called before initialise()");
  arkode_->advanceTo(t);
  syncState();
}

Real ArkodeSecondOrder::time() const { return arkode_->time(); }

Real ArkodeSecondOrder::stepSize() const {
  if (!options_.adaptive) return dt_;
  const Real last = arkode_->isInitialised() ? arkode_->lastStepSize() : 0;
  return last > 0 ? last : dt_;
}

void ArkodeSecondOrder::saveState(StateArchive& archive) const {
  if (!firstOrder_) throw Error("arkode: saveState() called before initialise()");
  arkode_->saveState(archive);
}

void ArkodeSecondOrder::restoreState(const StateArchive& archive) {
  if (!firstOrder_) throw Error("arkode: restoreState() called before initialise()");
  arkode_->restoreState(archive);
  syncState();
}

void ArkodeSecondOrder::syncState() {
  firstOrder_->unpack(arkode_->state(), u_, v_);
  steps_ = arkode_->statistics().steps;
}

}  // namespace mfwave
