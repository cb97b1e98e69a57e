// Extruded polygon: exact distances against walls and caps, side-wall and cap names and normals.

#include "geometry/ExtrudedPolygon.hpp"
#include "support/InputErrorKey.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace mfwave;

TEST(ExtrudedPolygon, DistancesNamesAndNormals) {
  // A right triangle with legs 2, from z = -1 to z = 1.
  const ExtrudedPolygon prism({Vec2(0, 0), Vec2(2, 0), Vec2(0, 2)}, -1, 1, "wedge");
  EXPECT_DOUBLE_EQ(prism.volume(), 4.0);
  EXPECT_DOUBLE_EQ(prism.signedDistance(Vec3(0.5, 0.2, 0)), -0.2);
  EXPECT_DOUBLE_EQ(prism.signedDistance(Vec3(0.5, 0.5, 0.9)), -0.1);
  EXPECT_DOUBLE_EQ(prism.signedDistance(Vec3(0.5, 0.5, 1.5)), 0.5);
  EXPECT_NEAR(prism.signedDistance(Vec3(0.5, -0.3, 1.4)), 0.5, 1e-15);  // beyond an edge: 3-4-5
  EXPECT_NEAR(prism.signedDistance(Vec3(1.5, 1.5, 0)), 1 / std::sqrt(2.0), 1e-15);
  EXPECT_EQ(prism.surfaceName(Vec3(0.5, 0.2, 0)), "wedge.edge0");
  EXPECT_EQ(prism.surfaceName(Vec3(1.5, 1.5, 0)), "wedge.edge1");
  EXPECT_EQ(prism.surfaceName(Vec3(0.1, 1, 0)), "wedge.edge2");
  EXPECT_EQ(prism.surfaceName(Vec3(0.5, 0.5, 0.9)), "wedge.top");
  EXPECT_EQ(prism.surfaceName(Vec3(0.5, 0.5, -0.95)), "wedge.bottom");
  EXPECT_NEAR((prism.normal(Vec3(1.5, 1.5, 0)) - Vec3(1, 1, 0) / std::sqrt(2.0)).norm(), 0, 1e-15);
  EXPECT_EQ(prism.normal(Vec3(0.5, 0.5, -0.95)), Vec3(0, 0, -1));
  EXPECT_EQ(prism.bounds().lower, Vec3(0, 0, -1));
  EXPECT_EQ(prism.bounds().upper, Vec3(2, 2, 1));
}

TEST(ExtrudedPolygon, Refusals) {
  using mfwave::testing::inputErrorKey;
  EXPECT_EQ(inputErrorKey([] { ExtrudedPolygon({Vec2(0, 0), Vec2(1, 0), Vec2(0, 1)}, 1, 1); }), "extruded_polygon.z1");
  EXPECT_EQ(inputErrorKey([] { ExtrudedPolygon({Vec2(0, 0), Vec2(1, 1), Vec2(1, 0), Vec2(0, 1)}, 0, 1, "w"); }),
            "w.vertices");
}
