// Half-space: signed distance along a tilted normal, its one surface, infinite bounds, refusals.

#include "geometry/HalfSpace.hpp"
#include "support/InputErrorKey.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace mfwave;

TEST(HalfSpace, DistanceAlongAnyNormal) {
  // The plane x + y = 1 (through (1, 0)), solid below-left; the normal is given unnormalised.
  const HalfSpace<2> h(Vec2(1, 0), Vec2(2, 2), "cut");
  EXPECT_NEAR(h.signedDistance(Vec2(0, 0)), -1 / std::sqrt(2.0), 1e-15);
  EXPECT_NEAR(h.signedDistance(Vec2(1, 1)), 1 / std::sqrt(2.0), 1e-15);
  EXPECT_NEAR(h.signedDistance(Vec2(0.5, 0.5)), 0, 1e-15);
  EXPECT_TRUE(h.inside(Vec2(-5, 3)));
  EXPECT_NEAR((h.normal(Vec2(7, 7)) - Vec2(1, 1) / std::sqrt(2.0)).norm(), 0, 1e-15);
  EXPECT_EQ(h.surfaceName(Vec2(0, 0)), "cut.plane");
  EXPECT_EQ(HalfSpace<3>(Vec3::Zero(), Vec3(0, 0, -1)).surfaceName(Vec3::Zero()), "plane");
}

TEST(HalfSpace, BoundsAreInfinite) {
  const HalfSpace<3> h(Vec3(0, 0, 0), Vec3(0, 0, 1));
  EXPECT_FALSE(h.bounds().finite());
  EXPECT_TRUE(h.bounds().contains(Vec3(1e300, -1e300, 0)));
}

TEST(HalfSpace, RefusesAZeroNormal) {
  using mfwave::testing::inputErrorKey;
  EXPECT_EQ(inputErrorKey([] { HalfSpace<3>(Vec3::Zero(), Vec3::Zero()); }), "half_space.normal");
  EXPECT_EQ(inputErrorKey([] { HalfSpace<2>(Vec2(INFINITY, 0), Vec2(1, 0), "floor"); }), "floor.point");
}
