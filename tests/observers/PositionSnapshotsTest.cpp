// PositionSnapshots: the positions at the first state at or after each time, one snapshot per
// state, the rest at the end; positions from a moved set or as X + u; non-finite states passed by.

#include "observers/PositionSnapshots.hpp"

#include <gtest/gtest.h>

#include <limits>

using namespace mfwave;

TEST(PositionSnapshots, TakesTheFirstStateAtOrAfterEachTimeAndTheRestAtTheEnd) {
  ParticleSet<1> line;
  line.add(Vec1(0), 1);
  line.add(Vec1(1), 1);
  PositionSnapshots<1> snaps(line, {0.0, 0.25, 0.3, 0.9, 1.5}, true);
  Vector u(2), v = Vector::Zero(2);
  u << 0.1, 0.2;
  snaps.begin({0, 0.0, u, v, 0.2});
  snaps.observe({1, 0.2, u, v, 0.2});  // before 0.25: nothing
  snaps.observe({2, 0.4, u, v, 0.2});  // past 0.25 and 0.3: one snapshot per state
  ASSERT_EQ(snaps.snapshots().size(), 2u);
  EXPECT_EQ(snaps.snapshots()[1].time, 0.4);
  EXPECT_DOUBLE_EQ(snaps.snapshots()[1].positions[0][1], 1.2);  // X + u
  u[0] = std::numeric_limits<Real>::quiet_NaN();
  snaps.observe({3, 0.6, u, v, 0.2});  // passed by
  EXPECT_EQ(snaps.snapshots().size(), 2u);
  u[0] = 0.5;
  snaps.end({4, 0.8, u, v, 0.2});  // the end takes 0.3, 0.9 and 1.5 (the run ended early)
  ASSERT_EQ(snaps.snapshots().size(), 5u);
  EXPECT_EQ(snaps.snapshots()[4].time, 0.8);
  EXPECT_DOUBLE_EQ(snaps.snapshots()[4].positions[0][0], 0.5);
}
