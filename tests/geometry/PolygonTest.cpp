// Polygon solid: an L shape's inside and outside, exact distances, edge names and normals, the
// same solid from a clockwise list.

#include "geometry/Polygon.hpp"
#include "support/InputErrorKey.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

using namespace mfwave;

namespace {

// The L: [0, 2] x [0, 1] plus [0, 1] x [1, 2], counter-clockwise from the origin.
std::vector<Vec2> lShape() {
  return {Vec2(0, 0), Vec2(2, 0), Vec2(2, 1), Vec2(1, 1), Vec2(1, 2), Vec2(0, 2)};
}

}  // namespace

TEST(Polygon, InsideOutsideAndDistances) {
  const Polygon l(lShape(), "ell");
  EXPECT_TRUE(l.inside(Vec2(0.5, 1.5)));
  EXPECT_TRUE(l.inside(Vec2(1.5, 0.5)));
  EXPECT_FALSE(l.inside(Vec2(1.5, 1.5)));
  EXPECT_DOUBLE_EQ(l.signedDistance(Vec2(0.5, 0.5)), -0.5);
  EXPECT_DOUBLE_EQ(l.signedDistance(Vec2(1.5, 1.25)), 0.25);
  EXPECT_NEAR(l.signedDistance(Vec2(1.3, 1.4)), 0.3, 1e-15);  // nearest the inner edge x = 1
  EXPECT_DOUBLE_EQ(l.signedDistance(Vec2(2, 0.5)), 0.0);
  EXPECT_DOUBLE_EQ(l.shape().area(), 3.0);
}

TEST(Polygon, EdgeNamesAndNormals) {
  const Polygon l(lShape(), "ell");
  EXPECT_EQ(l.surfaceName(Vec2(1, -0.1)), "ell.edge0");
  EXPECT_EQ(l.surfaceName(Vec2(1.9, 0.5)), "ell.edge1");
  EXPECT_EQ(l.surfaceName(Vec2(1.5, 1.05)), "ell.edge2");
  EXPECT_EQ(l.surfaceName(Vec2(1.05, 1.5)), "ell.edge3");
  EXPECT_EQ(l.surfaceName(Vec2(-0.2, 1.0)), "ell.edge5");
  EXPECT_NEAR((l.normal(Vec2(1.5, 1.05)) - Vec2(0, 1)).norm(), 0, 1e-15);
  EXPECT_NEAR((l.normal(Vec2(1.05, 1.5)) - Vec2(1, 0)).norm(), 0, 1e-15);
  EXPECT_NEAR((l.normal(Vec2(-0.2, 1.0)) - Vec2(-1, 0)).norm(), 0, 1e-15);
  EXPECT_EQ(Polygon(lShape()).surfaceName(Vec2(1, -0.1)), "edge0");
}

TEST(Polygon, ClockwiseListDescribesTheSameSolid) {
  std::vector<Vec2> reversed = lShape();
  std::reverse(reversed.begin(), reversed.end());
  const Polygon l(lShape()), r(reversed);
  // Points with one nearest edge (where several tie, either order may pick another of them).
  for (const Vec2& x : {Vec2(0.3, 1.6), Vec2(1.5, 1.4), Vec2(-1, 2.5), Vec2(1.2, 0.9)}) {
    EXPECT_DOUBLE_EQ(l.signedDistance(x), r.signedDistance(x));
    EXPECT_NEAR((l.normal(x) - r.normal(x)).norm(), 0, 1e-15);
  }
  // Reversed, edge i runs from the old vertex 5 - i to 4 - i: the bottom edge is edge 4.
  EXPECT_EQ(r.surfaceName(Vec2(1, -0.1)), "edge4");
}

TEST(Polygon, RefusesDegenerateAndSelfIntersectingPolygons) {
  using mfwave::testing::inputErrorKey;
  EXPECT_EQ(inputErrorKey([] { Polygon({Vec2(0, 0), Vec2(1, 0)}, "plate"); }), "plate.vertices");
  EXPECT_EQ(inputErrorKey([] { Polygon({Vec2(0, 0), Vec2(1, 1), Vec2(1, 0), Vec2(0, 1)}); }), "polygon.vertices");
}
