// The dispersion relation measured from simulations of the periodic lattice agrees with the FFT
// symbol once the integrator's own dispersion is added.

#include "spectra/MethodLatticeStencils.hpp"
#include "numerics/SimulatedDispersion.hpp"
#include "spectra/VeryWeakSphDispersion.hpp"
#include "core/Error.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace mfwave;

TEST(SimulatedDispersion, IntegratorFrequenciesAreTheKnownDiscreteRelations) {
  EXPECT_NEAR(integratorFrequency("central_difference", 1, 2), 2 * std::asin(1.0) / 2, 1e-15);  // at the limit
  EXPECT_TRUE(std::isnan(integratorFrequency("central_difference", 1.1, 2)));
  EXPECT_NEAR(integratorFrequency("newmark", 2, 0.1), 2 * std::atan(0.1) / 0.1, 1e-15);
  EXPECT_TRUE(std::isnan(integratorFrequency("arkode", 1, 0.1)));
  // Both tend to omega as dt -> 0.
  EXPECT_NEAR(integratorFrequency("leapfrog", 1, 1e-4), 1, 1e-8);
}

TEST(SimulatedDispersion, FiniteDifferenceSimulationPeaksFollowTheCentralDifferenceRelation) {
  const Real dx = 1, c = 1;
  const auto op = makePeriodicLatticeOperator<1>(finiteDifferenceInteriorStencil<1>(dx, c).acceleration, dx, 64);
  const DispersionSpectrum<1> spectrum(op);
  SimulatedDispersionOptions options;
  options.stepFraction = 0.9;
  const SimulatedDispersionResult run = simulateDispersion<1>(op, spectrum, options);
  EXPECT_NEAR(run.criticalStep, 1.0, 1e-12);  // 2 / omega_max = dx / c
  ASSERT_GT(run.points.size(), 20u);
  EXPECT_LT(run.largestError, 1e-6);
  // The integrator's dispersion is visible: at the highest wavenumbers central difference is
  // faster than the spatial relation by far more than the measurement error.
  const auto& last = run.points.back();
  EXPECT_GT(last.omegaMeasured / last.omegaSymbol - 1, 0.1);
}

TEST(SimulatedDispersion, VeryWeakSphIn2DAgreesOnTheAxisAndDiagonalForPAndS) {
  const Material material = Material::fromLame(2, 1, 1);
  const Real dx = 0.5;
  const auto vw = veryWeakSphInteriorStencil<2>(VeryWeakSphDispersionVariant::Consistent, "cubic_spline", 1.3,
                                                material, dx);
  const auto op = makePeriodicLatticeOperator<2>(vw.stencil, dx, 32);
  const DispersionSpectrum<2> spectrum(op);
  for (LatticeDirection direction : {LatticeDirection::Axis, LatticeDirection::Diagonal}) {
    SimulatedDispersionOptions options;
    options.direction = direction;
    options.stepFraction = 0.7;
    options.steps = 1024;
    const SimulatedDispersionResult run = simulateDispersion<2>(op, spectrum, options);
    int p = 0, s = 0;
    for (const auto& point : run.points) (point.polarisation == Polarisation::P ? p : s)++;
    EXPECT_GT(p, 5) << latticeDirectionName(direction);
    EXPECT_GT(s, 5) << latticeDirectionName(direction);
    EXPECT_LT(run.largestError, 1e-4) << latticeDirectionName(direction);
  }
}

TEST(SimulatedDispersion, NewmarkPeaksFollowTheTrapezoidalRelation) {
  const auto op = makePeriodicLatticeOperator<1>(finiteDifferenceInteriorStencil<1>(1, 1).acceleration, 1, 32);
  const DispersionSpectrum<1> spectrum(op);
  SimulatedDispersionOptions options;
  options.integrator = "newmark";
  options.stepFraction = 1.5;  // beyond the explicit limit: Newmark stays stable and lags
  options.steps = 1024;
  const SimulatedDispersionResult run = simulateDispersion<1>(op, spectrum, options);
  ASSERT_GT(run.points.size(), 5u);
  EXPECT_LT(run.largestError, 1e-6);
  EXPECT_LT(run.points.back().omegaMeasured / run.points.back().omegaSymbol, 0.9);
}

TEST(SimulatedDispersion, BadInputIsRefused) {
  const auto fd = finiteDifferenceInteriorStencil<1>(1, 1);
  const auto op = makePeriodicLatticeOperator<1>(fd.acceleration, 1, 16);
  const DispersionSpectrum<1> spectrum(op);
  SimulatedDispersionOptions options;
  options.stepFraction = 1.2;
  EXPECT_THROW(simulateDispersion<1>(op, spectrum, options), InputError);
  options.stepFraction = 0.5;
  options.steps = 10;
  EXPECT_THROW(simulateDispersion<1>(op, spectrum, options), InputError);
  options.steps = 128;
  options.integrator = "euler";
  EXPECT_THROW(simulateDispersion<1>(op, spectrum, options), InputError);
}
