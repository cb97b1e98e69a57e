#pragma once
// Any ARKODE explicit Runge-Kutta method on a second-order system u'' = a(t, u, u'): the system is
// viewed as y = [u; v], y' = [v; a] (SecondOrderAsFirstOrder) and driven by ArkodeExplicit, so a
// driver can swap it in for CentralDifference, Leapfrog or Newmark. Costs one acceleration per
// stage (4 per step for classic RK4), and RK methods are not symplectic: prefer them for accuracy
// studies and damped problems, the leapfrog family for long undamped runs.

#include "integrators/ArkodeExplicit.hpp"
#include "integrators/Integrator.hpp"
#include "systems/SecondOrderAsFirstOrder.hpp"

#include <memory>

namespace mfwave {

class ArkodeSecondOrder : public SecondOrderIntegrator {
 public:
  // Checks the options (table name, embedding for adaptive runs, tolerances) at once.
  explicit ArkodeSecondOrder(ArkodeOptions options = {});

  std::string name() const override { return "arkode"; }
  // Fixed-step mode: dt is the step (it replaces options.fixedStep). Adaptive mode: dt is the
  // initial step unless options.initialStep > 0.
  void initialise(SecondOrderSystem& system, Real t0, const Vector& u0, const Vector& v0, Real dt) override;
  void step() override;
  // Lands exactly on t through ARKODE's stop time; with a fixed step, t need not lie on the step
  // grid (the last step is shortened).
  void advanceTo(Real t) override;
  Real time() const override;
  long stepCount() const override { return steps_; }
  // The fixed step, or the last adaptive step (the initial step before the first).
  Real stepSize() const override;
  StateView state() const override { return {steps_, time(), u_, v_, stepSize()}; }

  // Fixed-step runs only (ArkodeExplicit::saveState).
  void saveState(StateArchive& archive) const override;
  void restoreState(const StateArchive& archive) override;

  const ArkodeExplicit& arkode() const { return *arkode_; }
  const ArkodeOptions& options() const { return options_; }

 private:
  void syncState();

  ArkodeOptions options_;
  std::unique_ptr<SecondOrderAsFirstOrder> firstOrder_;
  std::unique_ptr<ArkodeExplicit> arkode_;
  Real dt_ = 0;
  long steps_ = 0;
  Vector u_, v_;  // copies of the head and tail of y, refreshed after every step (StateView needs Vectors)
};

}  // namespace mfwave
