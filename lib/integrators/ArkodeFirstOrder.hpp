#pragma once
// Any ARKODE explicit Runge-Kutta method (ArkodeExplicit) as a FirstOrderIntegrator, fixed step
// (e.g. classic_rk4) or adaptive.
//
// Step-size rule (setStepSizeFunction): in a fixed-step run the rule's answer becomes the fixed
// step before every step (ArkodeExplicit::setFixedStep); in an adaptive run it bounds the steps
// ARKODE chooses (ArkodeExplicit::setMaxStep), re-evaluated before every step. advanceTo lands
// exactly on t in both cases (ARKODE's stop time shortens the last step).

#include "integrators/ArkodeExplicit.hpp"
#include "integrators/FirstOrderIntegrator.hpp"

#include <memory>

namespace mfwave {

class ArkodeFirstOrder : public FirstOrderIntegrator {
 public:
  // Checks the options (table name, embedding for adaptive runs, tolerances) at once.
  explicit ArkodeFirstOrder(ArkodeOptions options = {});

  std::string name() const override { return "arkode"; }
  // Fixed-step mode: dt is the step (it replaces options.fixedStep). Adaptive mode: dt is the
  // initial step unless options.initialStep > 0.
  void initialise(FirstOrderSystem& system, Real t0, const Vector& y0, Real dt) override;
  void step() override;
  void advanceTo(Real t) override;
  Real time() const override;
  long stepCount() const override { return steps_; }
  // The last step taken; before the first, the fixed step (fixed mode) or the initial step.
  Real stepSize() const override;
  const Vector& solution() const override;
  // ARKODE's count of F calls (classic RK4: 4 per step).
  double rhsEvaluations() const override;

  // Fixed-step runs only (ArkodeExplicit::saveState).
  void saveState(StateArchive& archive) const override;
  void restoreState(const StateArchive& archive) override;

  const ArkodeExplicit& arkode() const { return *arkode_; }
  const ArkodeOptions& options() const { return options_; }

 private:
  void requireInitialised(const char* what) const;
  // Applies the rule before a step: the fixed step, or the adaptive bound. Returns the rule's
  // answer (the current fixed step without a rule, 0 in adaptive runs without a rule).
  Real applyRule();

  ArkodeOptions options_;
  std::unique_ptr<ArkodeExplicit> arkode_;
  bool initialised_ = false;
  Real dt_ = 0;  // fixed mode: the fixed step without a rule; adaptive: the initial step
  long steps_ = 0;
};

}  // namespace mfwave
