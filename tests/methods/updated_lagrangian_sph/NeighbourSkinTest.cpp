// The skinned neighbour lists: rates from lists built at earlier positions (moved less than half
// the skin) equal those from fresh lists bit for bit, and moving further triggers a rebuild.

#include "UlsphTestSupport.hpp"

#include <gtest/gtest.h>

#include <random>

using namespace mfwave;

TEST(UlsphNeighbourSkin, StaleListsGiveTheSameRatesAndLargeMovesRebuild) {
  const ParticleSet<2> set = makeLattice<2>(Vec2::Zero(), Vec2::Ones(), 0.05);
  UpdatedLagrangianSphOptions options;
  options.viscosity.beta = 1;
  options.artificialStress.enabled = true;
  options.xsph = 0.5;
  UpdatedLagrangianSph<2> aged(set, options);
  EXPECT_EQ(aged.neighbourRebuilds(), 1);  // built once at construction
  const Real h = aged.smoothingLength();
  const Real halfSkin = 0.5 * options.neighbourSkin * 2 * h;  // skin kappa h / 2, kappa = 2
  // About pi (1.2 * 2.6)^2 = 31.8 per interior particle (list radius (1 + skin) 2h), fewer at the surface.
  EXPECT_GT(aged.meanNeighbourCount(), 20.0);
  EXPECT_LT(aged.meanNeighbourCount(), 33.0);

  std::mt19937 rng(5);
  std::uniform_real_distribution<Real> u(-1, 1);
  Vector y = aged.initialState();
  const auto& layout = aged.layout();
  for (Index i = 0; i < aged.particleCount(); ++i) {
    for (int a = 0; a < 2; ++a) {
      y[layout.position(i, a)] += 0.6 * halfSkin * u(rng) / std::sqrt(2.0);
      y[layout.velocity(i, a)] = 0.1 * u(rng);
    }
    y[layout.stress(i, 0)] = 0.2 * u(rng);
    y[layout.stress(i, 2)] = 0.2 * u(rng);
  }
  Vector agedRate(aged.size());
  aged.rhs(0, y, agedRate);
  EXPECT_EQ(aged.neighbourRebuilds(), 1);  // moved less than half the skin: no rebuild

  // A system built at the moved positions.
  ParticleSet<2> moved = set;
  for (Index i = 0; i < moved.size(); ++i) moved.setPosition(i, Vec2(y[layout.position(i, 0)], y[layout.position(i, 1)]));
  UpdatedLagrangianSph<2> fresh(moved, options);
  Vector freshRate(fresh.size());
  fresh.rhs(0, y, freshRate);
  EXPECT_EQ((agedRate - freshRate).cwiseAbs().maxCoeff(), 0.0);

  // One particle moves by more than half the skin: rebuild.
  y[layout.position(200, 0)] += 1.7 * halfSkin;  // at least 1.1 halfSkin from where it was built
  aged.rhs(0, y, agedRate);
  EXPECT_EQ(aged.neighbourRebuilds(), 2);
}

// A pair filter (a crack's visibility criterion) cuts the material in two: the rates of the
// particles on one side do not see the other side's velocities, and the lists keep only the
// pairs on one side, at the first build and at every rebuild.
TEST(UlsphNeighbourSkin, APairFilterSeparatesTheTwoSidesOfACrack) {
  const ParticleSet<2> set = makeLattice<2>(Vec2::Zero(), Vec2::Ones(), 0.05);
  const auto left = [&set](Index i) { return set.position(i)[0] < 0.5; };
  UpdatedLagrangianSphOptions options;
  options.interacts = [left](Index i, Index j) { return left(i) == left(j); };
  UpdatedLagrangianSph<2> cracked(set, options);
  for (Index i = 0; i < cracked.particleCount(); ++i)
    for (const Index j : cracked.neighbours().row(i)) ASSERT_EQ(left(i), left(j)) << i << " sees " << j;

  // the left half stretches: the right half, at rest, sees nothing of it
  Vector y = cracked.initialState();
  const auto& layout = cracked.layout();
  for (Index i = 0; i < cracked.particleCount(); ++i)
    if (left(i)) y[layout.velocity(i, 0)] = 0.3 * set.position(i)[0];
  Vector rate(cracked.size());
  cracked.rhs(0, y, rate);
  Real rightChange = 0, leftChange = 0;
  for (Index i = 0; i < cracked.particleCount(); ++i) {
    const Real density = std::abs(rate[layout.density(i)]);
    (left(i) ? leftChange : rightChange) = std::max(left(i) ? leftChange : rightChange, density);
  }
  EXPECT_EQ(rightChange, 0.0);
  EXPECT_GT(leftChange, 0.0);
  // a move beyond half the skin rebuilds the lists: still no pair across
  for (Index i = 0; i < cracked.particleCount(); ++i) y[layout.position(i, 1)] += 0.02;  // beyond skin h = 0.013
  cracked.rhs(0, y, rate);
  EXPECT_EQ(cracked.neighbourRebuilds(), 2);
  for (Index i = 0; i < cracked.particleCount(); ++i)
    for (const Index j : cracked.neighbours().row(i)) ASSERT_EQ(left(i), left(j));
}
