#include "core/Error.hpp"
#include "observers/GroupMeanRecorder.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

using namespace mfwave;

// Three particles with two components each; the group {0, 2}: the means of its u and v per
// component, named columns, the end state recorded once.
TEST(GroupMeanRecorder, RecordsTheGroupsMeanMotionPerComponent) {
  GroupMeanRecorder tip("tip", {0, 2}, 2);
  Vector u(6), v(6);
  u << 1, 2, 100, 200, 3, 6;
  v << -1, 0, 50, 50, 1, 4;
  tip.begin({0, 0.0, u, v});
  tip.observe({1, 0.5, u, v});
  tip.end({1, 0.5, u, v});  // the last step was already recorded
  const TimeSeries& s = tip.series();
  EXPECT_EQ(s.names(), (std::vector<std::string>{"u_x [m]", "u_y [m]", "v_x [m/s]", "v_y [m/s]"}));
  ASSERT_EQ(s.rows(), 2u);
  EXPECT_DOUBLE_EQ(s.column(0)[1], 2.0);
  EXPECT_DOUBLE_EQ(s.column(1)[1], 4.0);
  EXPECT_DOUBLE_EQ(s.column(2)[1], 0.0);
  EXPECT_DOUBLE_EQ(s.column(3)[1], 2.0);
}

TEST(GroupMeanRecorder, StopsAtANonFiniteMeanAndRefusesAnEmptyGroup) {
  GroupMeanRecorder tip("the plate's tip", {1}, 1);
  Vector u(2), v(2);
  u << 0, std::numeric_limits<Real>::quiet_NaN();
  v << 0, 0;
  try {
    tip.observe({7, 0.25, u, v});
    FAIL() << "a NaN mean must stop the run";
  } catch (const InstabilityError& e) {
    EXPECT_EQ(e.step(), 7);
    EXPECT_NE(std::string(e.what()).find("the plate's tip"), std::string::npos) << e.what();
  }
  EXPECT_THROW(GroupMeanRecorder("nobody", {}, 2), InputError);
  EXPECT_THROW(GroupMeanRecorder("four-d", {0}, 4), InputError);
}
