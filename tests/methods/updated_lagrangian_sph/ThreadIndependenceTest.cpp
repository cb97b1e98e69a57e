// The pair passes are gathers (row i writes only particle i), so the rates do not depend on the
// number of OpenMP threads, bit for bit. 61^2 = 3721 particles: above the size where the loops
// go parallel.

#include "UlsphTestSupport.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <random>

using namespace mfwave;

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
