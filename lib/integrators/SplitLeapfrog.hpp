#pragma once
// Leapfrog in kick-drift-kick form on a split first-order system y = [q; p]
// (SplitFirstOrderSystem: q' = Q(t, y), p' = P(t, y)), the staggered scheme SPH codes use for
// solids:
//   p_{n+1/2} = p_n + dt/2 P_n                       (kick; P_n kept from the previous step)
//   q*        = q_n + dt/2 Q_{n-1/2}                 (the midpoint configuration, extrapolated
//                                                     with the previous drift's rate; q_0 at the
//                                                     first step)
//   q_{n+1}   = q_n + dt Q_{n+1/2},  Q_{n+1/2} = Q(t_n + dt/2, [q*; p_{n+1/2}])   (drift)
//   p*        = p_{n+1/2} + dt/2 P_n                 (predictor, for a P that depends on p)
//   P_{n+1}   = P(t_{n+1}, [q_{n+1}; p*])
//   p_{n+1}   = p_{n+1/2} + dt/2 P_{n+1}             (kick)
// One configurationRate and one momentumRate call per step (an rhsEvaluations() of 1); P_0 is
// evaluated once at initialise (0.5). With Q = Q(p) and P = P(q) it is the Stormer-Verlet method:
// symplectic, time-reversible, second order, stable for omega dt < 2 with a bounded energy error.
//
// Accuracy (tests/integrators/FirstOrderIntegratorTest.cpp, docs/theory/time-integration.md):
//  - a P that depends on p (viscosity, dashpots) keeps second order through the predictor p*:
//    p* - p_{n+1} = O(dt^2), so P_{n+1} is O(dt^2) off and the kick adds O(dt^3) per step;
//  - the step may change from step to step (a step-size rule, advanceTo's shortened last step):
//    each step uses its own dt on both half kicks, and P_n is the rate at t_n whatever dt the
//    previous step had, so a step is a one-step map of (y_n, P_n) and the scheme stays second
//    order (the variable-step map is no longer symplectic);
//  - a Q that depends on q (the density rate -rho div v, the Jaumann terms of a stress rate, the
//    positions of moving particles) is evaluated at the midpoint q*, which is O(dt^2) from
//    q(t_n + dt/2): the drift is then a midpoint rule and the scheme stays second order. (Drifting
//    with Q at q_n, as the textbook scheme for Q = Q(p) does, would be a forward-Euler error
//    dt^2/2 (dQ/dq) Q per step: first order.) When Q does not depend on q, q* changes nothing and
//    the scheme is exactly the Stormer-Verlet method above. The cost is a copy of q per step.

#include "integrators/ExplicitFirstOrderIntegrator.hpp"
#include "systems/SplitFirstOrderSystem.hpp"

namespace mfwave {

class SplitLeapfrog : public ExplicitFirstOrderIntegrator {
 public:
  std::string name() const override { return "leapfrog"; }
  // Throws InputError("integrator.name") unless `system` is a SplitFirstOrderSystem; then as
  // every FirstOrderIntegrator, and evaluates P_0 = P(t0, y0) once.
  void initialise(FirstOrderSystem& system, Real t0, const Vector& y0, Real dt) override;

  // P_n at the current time (as used by the next opening kick).
  const Vector& momentumRate() const { return momentumRate_; }

 protected:
  void start() override;
  void advance(Real dt) override;
  // P_n and Q_{n-1/2} (with whether it is there yet).
  void saveHistory(StateArchive& archive) const override;
  void restoreHistory(const StateArchive& archive) override;

 private:
  SplitFirstOrderSystem* split_ = nullptr;
  Index nq_ = 0;             // configuration size
  Vector momentumRate_;      // P_n
  Vector configurationRate_; // Q (work)
  Vector pHalf_;             // p_{n+1/2} (work)
  Vector qStart_;            // q_n (work)
  bool haveConfigurationRate_ = false;  // configurationRate_ holds Q_{n-1/2}
};

}  // namespace mfwave
