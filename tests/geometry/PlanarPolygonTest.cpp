// Planar polygon: area and orientation, crossing-number containment, nearest edges, and the
// refusals of degenerate and self-intersecting vertex lists.

#include "core/Error.hpp"
#include "geometry/PlanarPolygon.hpp"
#include "support/InputErrorKey.hpp"

#include <gtest/gtest.h>

#include <string>

using namespace mfwave;

namespace {

using mfwave::testing::inputErrorProblem;

}  // namespace

TEST(PlanarPolygon, AreaAndOrientationOfEitherWinding) {
  const PlanarPolygon ccw({Vec2(0, 0), Vec2(2, 0), Vec2(2, 1), Vec2(0, 1)}, "p");
  const PlanarPolygon cw({Vec2(0, 0), Vec2(0, 1), Vec2(2, 1), Vec2(2, 0)}, "p");
  EXPECT_DOUBLE_EQ(ccw.area(), 2.0);
  EXPECT_DOUBLE_EQ(cw.area(), 2.0);
  EXPECT_TRUE(ccw.counterClockwise());
  EXPECT_FALSE(cw.counterClockwise());
  // Edge 0 is the bottom of ccw and the left side of cw; both normals point out.
  EXPECT_NEAR((ccw.outwardNormal(0) - Vec2(0, -1)).norm(), 0, 1e-15);
  EXPECT_NEAR((cw.outwardNormal(0) - Vec2(-1, 0)).norm(), 0, 1e-15);
  EXPECT_DOUBLE_EQ(cw.signedDistance(Vec2(1.5, 0.5)), -0.5);
  EXPECT_DOUBLE_EQ(ccw.signedDistance(Vec2(3, 0.5)), 1.0);
}

TEST(PlanarPolygon, ContainmentOfANonConvexPolygon) {
  // A U shape: the notch 1 < x < 2, y > 1 is outside.
  const PlanarPolygon u({Vec2(0, 0), Vec2(3, 0), Vec2(3, 2), Vec2(2, 2), Vec2(2, 1), Vec2(1, 1), Vec2(1, 2), Vec2(0, 2)},
                        "u");
  EXPECT_TRUE(u.contains(Vec2(0.5, 1.5)));
  EXPECT_TRUE(u.contains(Vec2(2.5, 1.5)));
  EXPECT_TRUE(u.contains(Vec2(1.5, 0.5)));
  EXPECT_FALSE(u.contains(Vec2(1.5, 1.5)));
  EXPECT_FALSE(u.contains(Vec2(1.5, 2.0)));  // level with two vertices
  EXPECT_DOUBLE_EQ(u.signedDistance(Vec2(1.5, 1.5)), 0.5);
  EXPECT_DOUBLE_EQ(u.area(), 5.0);
  EXPECT_EQ(u.nearestEdge(Vec2(1.5, 1.4)).edge, 4);  // the notch's floor, from vertex 4 to 5
}

TEST(PlanarPolygon, NearestEdgeAtAVertexIsTheOneFartherOut) {
  const PlanarPolygon square({Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0, 1)}, "s");
  // Beyond the corner (1, 0), further out in x than in -y: the right edge (edge 1).
  EXPECT_EQ(square.nearestEdge(Vec2(1.3, -0.1)).edge, 1);
  EXPECT_EQ(square.nearestEdge(Vec2(1.1, -0.3)).edge, 0);
  EXPECT_NEAR(square.nearestEdge(Vec2(1.3, -0.4)).distance, 0.5, 1e-15);
}

TEST(PlanarPolygon, RefusesDegenerateAndSelfIntersectingLists) {
  using mfwave::testing::inputErrorKey;
  EXPECT_EQ(inputErrorKey([] { PlanarPolygon({Vec2(0, 0), Vec2(1, 0)}, "hole.vertices"); }), "hole.vertices");
  EXPECT_NE(inputErrorProblem([] { PlanarPolygon({Vec2(0, 0), Vec2(1, 0)}, "k"); }).find("at least 3"), std::string::npos);
  EXPECT_NE(inputErrorProblem([] { PlanarPolygon({Vec2(0, 0), Vec2(1, 0), Vec2(1, 0), Vec2(0, 1)}, "k"); }).find("coincide"),
            std::string::npos);
  // A bow tie: edges 0 and 2 cross.
  const std::string bowTie =
      inputErrorProblem([] { PlanarPolygon({Vec2(0, 0), Vec2(1, 1), Vec2(1, 0), Vec2(0, 1)}, "k"); });
  EXPECT_NE(bowTie.find("self-intersecting"), std::string::npos) << bowTie;
  EXPECT_NE(bowTie.find("edge0 and edge2"), std::string::npos) << bowTie;
  // Two squares touching at one vertex (a figure eight through (1, 1)).
  EXPECT_NE(inputErrorProblem([] {
              PlanarPolygon({Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(2, 1), Vec2(2, 2), Vec2(1, 2), Vec2(1, 1), Vec2(0, 1)},
                            "k");
            }).find("self-intersecting"),
            std::string::npos);
  // Collinear points, and a spike that folds back on itself.
  EXPECT_NE(inputErrorProblem([] { PlanarPolygon({Vec2(0, 0), Vec2(1, 0), Vec2(2, 0)}, "k"); }).find("self-intersecting"),
            std::string::npos);
  EXPECT_NE(inputErrorProblem([] { PlanarPolygon({Vec2(0, 0), Vec2(2, 0), Vec2(1, 0), Vec2(1, 1)}, "k"); })
                .find("fold back"),
            std::string::npos);
}
