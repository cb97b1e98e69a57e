// The zero-energy-mode indicator on a 2-D lattice ([0, 1]^2, dp = 0.02, h = 1.3 dp): a smooth
// velocity field is close to its kernel average (small zigzag, the free surface's one-sided
// average dominating), a particle-scale checkerboard is not; the spacing ratio reads the lattice.

#include "UlsphTestSupport.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace mfwave;

namespace {

struct Lattice {
  ParticleSet<2> set = makeLattice<2>(Vec2::Zero(), Vec2::Ones(), 0.02);
  UpdatedLagrangianSph<2> system{set, UpdatedLagrangianSphOptions{}};
};

}  // namespace

TEST(UlsphZeroEnergyModes, SmoothFieldIsSmallCheckerboardIsLarge) {
  Lattice lattice;
  const Index n = lattice.system.particleCount();
  Vector smooth(2 * n), checker(2 * n);
  for (Index i = 0; i < n; ++i) {
    const Vec2 x = lattice.set.position(i);
    smooth[2 * i] = std::cos(2 * M_PI * x[1]) + 0.5;
    smooth[2 * i + 1] = std::sin(2 * M_PI * x[0]);
    const long ix = std::lround(x[0] / 0.02), iy = std::lround(x[1] / 0.02);
    const Real sign = (ix + iy) % 2 == 0 ? 1.0 : -1.0;
    checker[2 * i] = sign;
    checker[2 * i + 1] = 0.3 * sign;
  }
  const ZeroEnergyModeIndicator a = lattice.system.zeroEnergyModes(lattice.system.initialState(smooth));
  const ZeroEnergyModeIndicator b = lattice.system.zeroEnergyModes(lattice.system.initialState(checker));
  const ZeroEnergyModeIndicator rest = lattice.system.zeroEnergyModes(lattice.system.initialState());
  std::printf("zigzag: smooth %.4f (worst particle %ld), checkerboard %.4f, spacing ratio %.6f\n", a.zigzag,
              static_cast<long>(a.zigzagWorstParticle), b.zigzag, a.minimumSpacingRatio);
  EXPECT_LT(a.zigzag, 0.05);
  EXPECT_GT(b.zigzag, 0.5);
  EXPECT_EQ(rest.zigzag, 0.0);
  EXPECT_EQ(rest.zigzagWorstParticle, -1);
  EXPECT_NEAR(a.minimumSpacingRatio, 1.0, 1e-9);
  // The smooth field's worst particle sits on the free surface, where the average is one-sided.
  const Vec2 worst = lattice.set.position(a.zigzagWorstParticle);
  EXPECT_TRUE(worst.minCoeff() < 0.05 || worst.maxCoeff() > 0.95);
}

TEST(UlsphZeroEnergyModes, SpacingRatioSeesTwoParticlesClosingIn) {
  Lattice lattice;
  Vector y = lattice.system.initialState();
  const auto& layout = lattice.system.layout();
  // Move particle 30 (interior row 0) 40 % of the way towards its right neighbour.
  y[layout.position(30, 0)] += 0.4 * 0.02;
  const ZeroEnergyModeIndicator z = lattice.system.zeroEnergyModes(y);
  EXPECT_NEAR(z.minimumSpacingRatio, 0.6, 1e-9);
}
