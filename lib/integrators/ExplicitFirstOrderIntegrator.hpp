#pragma once
// Bookkeeping shared by mfwave's own one-step integrators of y' = F(t, y) (forward Euler, the
// predictor-corrector, the split leapfrog): the bound system, the state y, the clock, the step
// counter and the count of right-hand-side evaluations. Derived classes implement advance(dt).
//
// The step: a rule's answer before every step (FirstOrderIntegrator::setStepSizeFunction), or the
// step given to initialise. The clock: while the step stays the same, t = t_origin + k dt (not a
// running sum), so a fixed-step run stays on its step grid; a new step size starts a new origin.
// advanceTo(t) lands exactly on t: the step that would pass t (or end within 1e-9 of a step of it)
// is shortened to end there, and the time is set to t itself.

#include "integrators/FirstOrderIntegrator.hpp"

namespace mfwave {

class ExplicitFirstOrderIntegrator : public FirstOrderIntegrator {
 public:
  // Checks the initial state (checkInitialState), binds the system, resets the clock and the
  // counters, then calls start().
  void initialise(FirstOrderSystem& system, Real t0, const Vector& y0, Real dt) override;
  // One step of the rule's size (or of the fixed step).
  void step() override;
  // Steps of the rule's size (or the fixed step) with the last one shortened to land on t;
  // t need not lie on the step grid. Throws InputError("end_time") for t before time().
  void advanceTo(Real t) override;

  Real time() const override { return time_; }
  long stepCount() const override { return steps_; }
  // The last step taken (shortened or not); before the first step, the step given to initialise.
  Real stepSize() const override { return lastStep_; }
  const Vector& solution() const override { return y_; }
  double rhsEvaluations() const override { return evaluations_; }

  // y, the clock (its origin, step and count, so that a restored run stays on the same grid), the
  // counters, the bound system's own state and the rule's history (saveHistory).
  void saveState(StateArchive& archive) const final;
  void restoreState(const StateArchive& archive) final;

 protected:
  // After binding, before any step (the leapfrog evaluates its first momentum rate here).
  virtual void start() {}
  // y_ from time_ to time_ + dt; adds its evaluations to evaluations_. The clock is advanced by
  // the caller afterwards.
  virtual void advance(Real dt) = 0;
  // What a derived rule carries between steps beyond y (none by default).
  virtual void saveHistory(StateArchive& archive) const { (void)archive; }
  virtual void restoreHistory(const StateArchive& archive) { (void)archive; }

  FirstOrderSystem* system_ = nullptr;
  Vector y_;
  Real time_ = 0;
  double evaluations_ = 0;

 private:
  void requireInitialised(const char* what) const;
  // One step of size dt; with `landing`, the time becomes exactly landOn afterwards.
  void takeStep(Real dt, bool landing, Real landOn);

  long steps_ = 0;
  Real nominalStep_ = 0;  // the step given to initialise (used when there is no rule)
  Real lastStep_ = 0;
  Real clockOrigin_ = 0;  // clock: time_ = clockOrigin_ + clockSteps_ * clockStep_
  Real clockStep_ = 0;
  long clockSteps_ = 0;
};

}  // namespace mfwave
