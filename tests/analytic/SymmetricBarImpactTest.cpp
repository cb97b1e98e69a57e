#include "analytic/SymmetricBarImpact.hpp"

#include "core/Error.hpp"

#include <gtest/gtest.h>

using namespace mfwave;

TEST(SymmetricBarImpact, StatesBehindAndAheadOfTheFronts) {
  const SymmetricBarImpact bar(1.0, 2.0, 3.0, 0.5);
  EXPECT_DOUBLE_EQ(bar.interfaceStress(), -3.0);  // -rho c v0
  EXPECT_DOUBLE_EQ(bar.frontPosition(0.25), 0.5);
  // behind the fronts: at rest, compressed
  EXPECT_DOUBLE_EQ(bar.velocity(0.1, 0.25), 0.0);
  EXPECT_DOUBLE_EQ(bar.stress(-0.4, 0.25), -3.0);
  // ahead: the initial motion, unstressed
  EXPECT_DOUBLE_EQ(bar.velocity(-0.6, 0.25), 0.5);
  EXPECT_DOUBLE_EQ(bar.velocity(0.6, 0.25), -0.5);
  EXPECT_DOUBLE_EQ(bar.stress(0.6, 0.25), 0.0);
  // at a front: the mean of the two sides
  EXPECT_DOUBLE_EQ(bar.velocity(0.5, 0.25), -0.25);
  EXPECT_DOUBLE_EQ(bar.stress(-0.5, 0.25), -1.5);
}

TEST(SymmetricBarImpact, MomentumAndTheJumpConditions) {
  // Total momentum stays zero; across the right-going front sigma jumps by -rho c times the jump of v.
  const SymmetricBarImpact bar(1.0, 1.0, 1.0, 0.1);
  const Real t = 0.3;
  const Real jumpV = bar.velocity(0.31, t) - bar.velocity(0.29, t);
  const Real jumpS = bar.stress(0.31, t) - bar.stress(0.29, t);
  EXPECT_NEAR(jumpS, -1.0 * 1.0 * jumpV, 1e-15);
  EXPECT_DOUBLE_EQ(bar.velocity(-0.7, t) + bar.velocity(0.7, t), 0.0);
}

TEST(SymmetricBarImpact, RejectsBadInput) {
  EXPECT_THROW(SymmetricBarImpact(0.0, 1.0, 1.0, 1.0), InputError);
  EXPECT_THROW(SymmetricBarImpact(1.0, -1.0, 1.0, 1.0), InputError);
  const SymmetricBarImpact bar(1.0, 1.0, 1.0, 1.0);
  try {
    bar.velocity(0.0, 1.5);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "time");
  }
}
