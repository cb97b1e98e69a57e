// Capped cylinder: exact distance off a tilted axis, the side / bottom / top names and normals,
// bounds of the end discs, refusals.

#include "geometry/Cylinder.hpp"
#include "support/InputErrorKey.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace mfwave;

TEST(Cylinder, AxisAlignedDistancesAndNames) {
  const Cylinder c(Vec3(0, 0, 0), Vec3(0, 0, 4), 1.0, "pin");
  EXPECT_DOUBLE_EQ(c.signedDistance(Vec3(0, 0, 2)), -1.0);
  EXPECT_NEAR(c.signedDistance(Vec3(0.5, 0, 3.8)), -0.2, 1e-15);
  EXPECT_DOUBLE_EQ(c.signedDistance(Vec3(3, 0, 2)), 2.0);
  EXPECT_DOUBLE_EQ(c.signedDistance(Vec3(0, 0, -0.5)), 0.5);
  EXPECT_DOUBLE_EQ(c.signedDistance(Vec3(4, 0, 8)), 5.0);  // beyond the top rim: 3-4-5
  EXPECT_EQ(c.surfaceName(Vec3(0.9, 0, 2)), "pin.side");
  EXPECT_EQ(c.surfaceName(Vec3(0, 0.2, 0.05)), "pin.bottom");
  EXPECT_EQ(c.surfaceName(Vec3(0, 0.2, 3.99)), "pin.top");
  EXPECT_EQ(c.normal(Vec3(0, 0.2, 0.05)), Vec3(0, 0, -1));
  EXPECT_EQ(c.normal(Vec3(0, 0.2, 4.5)), Vec3(0, 0, 1));
  EXPECT_NEAR((c.normal(Vec3(0, -0.9, 2)) - Vec3(0, -1, 0)).norm(), 0, 1e-15);
}

TEST(Cylinder, TiltedAxis) {
  const Vec3 bottom(1, 1, 1), axis = Vec3(1, 2, 2) / 3.0;
  const Cylinder c(bottom, bottom + 3 * axis, 0.5);
  const Vec3 across = Vec3(2, -1, 0).normalized();  // perpendicular to the axis
  EXPECT_NEAR(c.signedDistance(bottom + 1.5 * axis + 0.2 * across), -0.3, 1e-14);
  EXPECT_NEAR(c.signedDistance(bottom + 1.5 * axis + 0.9 * across), 0.4, 1e-14);
  EXPECT_NEAR(c.signedDistance(bottom - 0.25 * axis), 0.25, 1e-14);
  EXPECT_NEAR((c.normal(bottom + 1.5 * axis + 0.9 * across) - across).norm(), 0, 1e-14);
  EXPECT_EQ(c.surfaceName(bottom - 0.25 * axis), "bottom");
  // Each end disc reaches radius * sqrt(1 - a_i^2) along axis i.
  const Bounds<3> b = c.bounds();
  EXPECT_NEAR(b.lower.x(), 1 - 0.5 * std::sqrt(1 - 1.0 / 9), 1e-14);
  EXPECT_NEAR(b.upper.z(), 1 + 2 + 0.5 * std::sqrt(1 - 4.0 / 9), 1e-14);
}

TEST(Cylinder, RefusesZeroRadiusAndLength) {
  using mfwave::testing::inputErrorKey;
  EXPECT_EQ(inputErrorKey([] { Cylinder(Vec3(0, 0, 0), Vec3(0, 0, 1), 0.0); }), "cylinder.radius");
  EXPECT_EQ(inputErrorKey([] { Cylinder(Vec3(0, 0, 1), Vec3(0, 0, 1), 1.0, "rod"); }), "rod.top");
}
