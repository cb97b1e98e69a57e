// The pair passes are gathers (row i writes only particle i), so the rates do not depend on the
// number of OpenMP threads, bit for bit: the fused sweep of rhs, and the separate passes of
// configurationRate and momentumRate, with and without the kernel-gradient correction. 61^2 = 3721
// particles: above the size where the loops go parallel.

#include "UlsphTestSupport.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <random>

using namespace mfwave;

namespace {

UpdatedLagrangianSphOptions threadTestOptions(bool corrected, DensityUpdate density) {
  UpdatedLagrangianSphOptions options;
  options.viscosity.alpha = 0.5;
  options.viscosity.beta = 1;
  options.artificialStress.enabled = true;
  options.density = density;
  options.xsph = 0.3;
  options.kernelGradientCorrection = corrected;
  return options;
}

Vector perturbedState(const UpdatedLagrangianSph<2>& system) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<Real> u(-1, 1);
  Vector y = system.initialState();
  const auto& layout = system.layout();
  for (Index i = 0; i < system.particleCount(); ++i) {
    for (int a = 0; a < 2; ++a) {
      y[layout.position(i, a)] += 0.002 * u(rng);
      y[layout.velocity(i, a)] = 0.1 * u(rng);
    }
    for (int c = 0; c < 3; ++c) y[layout.stress(i, c)] = 0.2 * u(rng);
    y[layout.energy(i)] = 0.01 * (1 + u(rng));
  }
  return y;
}

// rhs, then configurationRate and momentumRate (the leapfrog's separate passes), stacked.
Vector allRates(UpdatedLagrangianSph<2>& system, const Vector& y, int threads) {
  const int saved = omp_get_max_threads();
  omp_set_num_threads(threads);
  const Index nq = system.configurationSize();
  Vector rates(2 * system.size());
  system.rhs(0, y, rates.head(system.size()));
  system.configurationRate(0, y, rates.segment(system.size(), nq));
  system.momentumRate(0, y, rates.tail(system.size() - nq));
  omp_set_num_threads(saved);
  return rates;
}

}  // namespace

TEST(UlsphThreads, FusedAndSeparatePassesDoNotDependOnTheThreadCount) {
  const ParticleSet<2> set = makeLattice<2>(Vec2::Zero(), Vec2::Ones(), 1.0 / 60);
  for (bool corrected : {false, true}) {
    for (DensityUpdate density : {DensityUpdate::Continuity, DensityUpdate::Summation}) {
      UpdatedLagrangianSph<2> system(set, threadTestOptions(corrected, density));
      const Vector y = perturbedState(system);
      const Vector one = allRates(system, y, 1);
      const Vector two = allRates(system, y, 2);
      EXPECT_EQ((one - two).cwiseAbs().maxCoeff(), 0.0) << "corrected " << corrected;
      // The fused sweep of rhs gives the separate passes' rates.
      const Index size = system.size();
      EXPECT_EQ((one.head(size) - one.tail(size)).cwiseAbs().maxCoeff(), 0.0) << "corrected " << corrected;
    }
  }
}

TEST(UlsphThreads, RatesAndDiagnosticsDoNotDependOnTheThreadCount) {
  const ParticleSet<2> set = makeLattice<2>(Vec2::Zero(), Vec2::Ones(), 1.0 / 60);
  UpdatedLagrangianSphOptions options;
  options.viscosity.beta = 1;
  options.artificialStress.enabled = true;
  options.density = DensityUpdate::Summation;
  options.xsph = 0.3;
  UpdatedLagrangianSph<2> system(set, options);
  ASSERT_GT(system.particleCount(), 3000);
  std::mt19937 rng(9);
  std::uniform_real_distribution<Real> u(-1, 1);
  Vector y = system.initialState();
  const auto& layout = system.layout();
  for (Index i = 0; i < system.particleCount(); ++i) {
    for (int a = 0; a < 2; ++a) {
      y[layout.position(i, a)] += 0.002 * u(rng);
      y[layout.velocity(i, a)] = 0.1 * u(rng);
    }
    for (int c = 0; c < 3; ++c) y[layout.stress(i, c)] = 0.2 * u(rng);
    y[layout.energy(i)] = 0.01 * (1 + u(rng));
  }
  const int saved = omp_get_max_threads();
  omp_set_num_threads(1);
  Vector one(system.size());
  system.rhs(0, y, one);
  const ZeroEnergyModeIndicator zOne = system.zeroEnergyModes(y);
  omp_set_num_threads(2);
  Vector two(system.size());
  system.rhs(0, y, two);
  const ZeroEnergyModeIndicator zTwo = system.zeroEnergyModes(y);
  omp_set_num_threads(saved);
  EXPECT_EQ((one - two).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(zOne.zigzag, zTwo.zigzag);
  EXPECT_EQ(zOne.minimumSpacingRatio, zTwo.minimumSpacingRatio);
}
