// Ball: exact distance, radial normal, its surface name, bounds, refusals.

#include "geometry/Ball.hpp"
#include "support/InputErrorKey.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace mfwave;

TEST(Ball, DistanceNormalAndName) {
  const Ball<3> ball(Vec3(1, 2, 3), 2.0, "hole");
  EXPECT_DOUBLE_EQ(ball.signedDistance(Vec3(1, 2, 3)), -2.0);
  EXPECT_DOUBLE_EQ(ball.signedDistance(Vec3(1, 2, 6)), 1.0);
  EXPECT_DOUBLE_EQ(ball.signedDistance(Vec3(1, 3.5, 3)), -0.5);
  EXPECT_EQ(ball.normal(Vec3(1, 2, 7)), Vec3(0, 0, 1));
  EXPECT_NEAR((ball.normal(Vec3(2, 3, 3)) - Vec3(1, 1, 0) / std::sqrt(2.0)).norm(), 0, 1e-15);
  EXPECT_NEAR(ball.normal(Vec3(1, 2, 3)).norm(), 1.0, 1e-15);  // any unit vector at the centre
  EXPECT_EQ(ball.surfaceName(Vec3(0, 0, 0)), "hole.surface");
  EXPECT_EQ(Ball<2>(Vec2(0, 0), 1).surfaceName(Vec2(3, 0)), "surface");
  EXPECT_EQ(ball.bounds().lower, Vec3(-1, 0, 1));
  EXPECT_EQ(ball.bounds().upper, Vec3(3, 4, 5));
}

TEST(Ball, RefusesAZeroOrNegativeRadius) {
  using mfwave::testing::inputErrorKey;
  EXPECT_EQ(inputErrorKey([] { Ball<2>(Vec2(0, 0), 0.0); }), "ball.radius");
  EXPECT_EQ(inputErrorKey([] { Ball<3>(Vec3(0, 0, 0), -1.0, "hole"); }), "hole.radius");
  EXPECT_EQ(inputErrorKey([] { Ball<3>(Vec3(0, 0, 0), INFINITY); }), "ball.radius");
}
