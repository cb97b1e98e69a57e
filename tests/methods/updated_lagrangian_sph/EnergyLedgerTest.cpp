// The energy ledger on a free 2-D block (plane strain, [0, 1]^2, dp = 0.05, lambda = mu = rho = 1)
// set moving in its fundamental compression mode v = v0 (cos(pi x), cos(pi y) / 2), integrated with a local
// kick-drift-kick leapfrog at the stable step for t in [0, 0.6] (about half a period: the kinetic
// energy turns into strain energy and partly back).
//  - alpha = 0: kinetic + internal is conserved to the leapfrog's O(dt^2) error, and the internal
//    energy equals the strain energy to O(strain) (hypoelasticity is not exactly hyperelastic).
//  - alpha > 0: the viscosity removes kinetic energy into the internal energy, the ledger counts
//    it, and kinetic + strain + dissipated stays constant.
//  - loads: with a body force, a traction and a prescribed velocity, kinetic + internal - loadWork
//    is conserved.

#include "UlsphTestSupport.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace mfwave;

namespace {

constexpr Real kV0 = 0.01;

struct LedgerRun {
  UpdatedLagrangianSphEnergy start, end;
  Real largestBalanceDrift = 0;         // max |(kinetic + internal - loadWork)(t) - (.)(0)| / E0
  Real largestStrainMismatch = 0;       // max |internal - strain - dissipated + R work| / E0
  Real largestMechanicalDrift = 0;      // max |kinetic + strain + dissipated - R work - loadWork - E0| / E0
  Real smallestKinetic = 1e300;         // min kinetic / E0
  int steps = 0;
};

LedgerRun runBlock(UpdatedLagrangianSphOptions options, bool loads, Real stepFactor = 1) {
  const ParticleSet<2> set = makeLattice<2>(Vec2::Zero(), Vec2::Ones(), 0.05);
  UpdatedLagrangianSph<2> system(set, options);
  const Index n = system.particleCount();
  if (loads) {
    std::vector<Index> bottom, top, left;
    for (Index i = 0; i < n; ++i) {
      const Vec2 x = set.position(i);
      if (x[1] < 1e-9) bottom.push_back(i);
      if (x[1] > 1 - 1e-9) top.push_back(i);
      if (x[0] < 1e-9 && x[1] > 1e-9 && x[1] < 1 - 1e-9) left.push_back(i);
    }
    system.prescribeVelocity(bottom, Vec2(0, 1), TimeFunction::ramp(0, 0.3, 0.5 * kV0));
    system.addTraction(top, Vec2(0.002, -0.01), TimeFunction::constant(1), 0.05);
    system.fixParticles(left);
  }
  Vector v(2 * n);
  for (Index i = 0; i < n; ++i) {
    const Vec2 x = set.position(i);
    v[2 * i] = kV0 * std::cos(M_PI * x[0]);
    v[2 * i + 1] = 0.5 * kV0 * std::cos(M_PI * x[1]);
  }
  const Vector y0 = system.initialState(v);
  test::LocalLeapfrog stepper(system, y0);
  LedgerRun run;
  run.start = system.energy(y0);
  const Real e0 = run.start.kinetic + run.start.strain;
  const Real end = 0.6;
  const Real dt = end / std::ceil(end / (stepFactor * system.stableStep(y0)));
  while (stepper.time() < end - 0.5 * dt) {
    stepper.step(dt);
    ++run.steps;
    const UpdatedLagrangianSphEnergy e = system.energy(stepper.state());
    run.largestBalanceDrift = std::max(run.largestBalanceDrift, std::abs(e.balance() - run.start.balance()) / e0);
    run.largestStrainMismatch = std::max(
        run.largestStrainMismatch,
        std::abs(e.internal - e.strain - e.viscousDissipation + e.artificialStressWork) / e0);
    run.largestMechanicalDrift = std::max(
        run.largestMechanicalDrift,
        std::abs(e.kinetic + e.strain + e.viscousDissipation - e.artificialStressWork - e.loadWork - e0) / e0);
    run.smallestKinetic = std::min(run.smallestKinetic, e.kinetic / e0);
  }
  run.end = system.energy(stepper.state());
  std::printf("ledger: %d steps, balance drift %.2e, internal-strain %.2e, mechanical drift %.2e, min kinetic %.3f, "
              "dissipated %.3e, load work %.3e (E0 %.3e)\n",
              run.steps, run.largestBalanceDrift, run.largestStrainMismatch, run.largestMechanicalDrift,
              run.smallestKinetic, run.end.viscousDissipation / e0, run.end.loadWork / e0, e0);
  return run;
}

}  // namespace

TEST(UlsphEnergyLedger, WithoutViscosityKineticPlusInternalIsConserved) {
  UpdatedLagrangianSphOptions options;
  options.viscosity.alpha = 0;
  const LedgerRun run = runBlock(options, false);
  EXPECT_LT(run.smallestKinetic, 0.5);  // the energy really went into strain and back
  EXPECT_LT(run.largestBalanceDrift, 2e-3);
  EXPECT_LT(run.largestStrainMismatch, 2e-3);
  EXPECT_EQ(run.end.viscousDissipation, 0.0);
  EXPECT_EQ(run.end.loadWork, 0.0);
  // The drift is the leapfrog's: half the step, a quarter of the drift (measured ratio below).
  const LedgerRun finer = runBlock(options, false, 0.5);
  std::printf("balance drift ratio for dt / 2: %.2f\n", run.largestBalanceDrift / finer.largestBalanceDrift);
  EXPECT_GT(run.largestBalanceDrift / finer.largestBalanceDrift, 3.0);
}

TEST(UlsphEnergyLedger, ViscosityDissipatesAndTheLedgerCountsIt) {
  UpdatedLagrangianSphOptions options;
  options.viscosity.alpha = 1;
  options.viscosity.beta = 1;
  const LedgerRun run = runBlock(options, false);
  const Real e0 = run.start.kinetic + run.start.strain;
  EXPECT_GT(run.end.viscousDissipation / e0, 1e-3);
  EXPECT_LT(run.largestBalanceDrift, 2e-3);
  EXPECT_LT(run.largestMechanicalDrift, 2e-3);
}

TEST(UlsphEnergyLedger, LoadsAndConstraintsAreInTheLoadWork) {
  UpdatedLagrangianSphOptions options;
  options.viscosity.alpha = 0.5;
  options.bodyForce = {0.0, -0.02, 0.0};
  const LedgerRun run = runBlock(options, true);
  const Real e0 = run.start.kinetic + run.start.strain;
  EXPECT_GT(std::abs(run.end.loadWork) / e0, 0.1);  // the loads did real work
  EXPECT_LT(run.largestBalanceDrift, 2e-3);
}
