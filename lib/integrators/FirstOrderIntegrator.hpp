#pragma once
// Integrators of a first-order system y' = F(t, y) (lib/systems/FirstOrderSystem.hpp), for the
// updated-Lagrangian SPH and any other method written in first-order form.
//
// They are Integrators, so the TimeLoop drives them and observers see them. Their StateView
// carries the whole state y in `displacement` and an empty `velocity`: only observers that know the
// system's layout (the method's own) interpret y.
//
// The step may change from step to step: setStepSizeFunction installs a rule (the CFL, viscous and
// force criteria of a particle method) that is asked for the next step before every step. The
// integrators never see particles.

#include "integrators/Integrator.hpp"
#include "systems/FirstOrderSystem.hpp"

#include <functional>

namespace mfwave {

class FirstOrderIntegrator : public Integrator {
 public:
  using StepSizeFunction = std::function<Real(Real t, const Vector& y)>;

  // Binds the system (it must outlive the integrator's use) and sets y(t0) = y0 with first step dt.
  // Throws InputError("initial_state") for a wrong size or non-finite entries, InputError("time_step")
  // unless dt > 0 and finite.
  virtual void initialise(FirstOrderSystem& system, Real t0, const Vector& y0, Real dt) = 0;

  // Before every step, dt = rule(t, y). A non-positive or non-finite answer throws
  // InstabilityError naming the step and time. An empty function keeps dt fixed.
  void setStepSizeFunction(StepSizeFunction rule) { stepSizeRule_ = std::move(rule); }

  // The current state y(time()).
  virtual const Vector& solution() const = 0;
  // Calls of F (or of its parts: a configuration and a momentum evaluation count one half each).
  virtual double rhsEvaluations() const = 0;
  // Whether a step-size rule is installed.
  bool hasStepSizeFunction() const { return static_cast<bool>(stepSizeRule_); }

  StateView state() const override { return {stepCount(), time(), solution(), empty_, stepSize()}; }

 protected:
  // The step to take next: the rule's answer, or `current` without a rule.
  Real nextStepSize(Real current) const;

 private:
  StepSizeFunction stepSizeRule_;
  Vector empty_;
};

// What every FirstOrderIntegrator::initialise checks first: y0 has the system's size (> 0) and is
// finite, t0 is finite, dt is positive and finite. Throws InputError ("initial_state",
// "start_time", "time_step").
void checkInitialState(const FirstOrderSystem& system, Real t0, const Vector& y0, Real dt);

}  // namespace mfwave
