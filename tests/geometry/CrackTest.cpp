// Cracks: a segment in 2-D and planar polygons in 3-D cut the pairs whose segment crosses them
// and no others; tips and points on the crack's line; the collection's visibility; refusals.

#include "geometry/Cracks.hpp"
#include "support/InputErrorKey.hpp"

#include <gtest/gtest.h>

using namespace mfwave;

TEST(Crack2, CutsThePairsItSeparates) {
  const Crack<2> crack(Vec2(0, 0.5), Vec2(1, 0.5));
  EXPECT_TRUE(crack.crosses(Vec2(0.5, 0.4), Vec2(0.5, 0.6)));
  EXPECT_TRUE(crack.crosses(Vec2(0.2, 0.9), Vec2(0.8, 0.1)));
  EXPECT_FALSE(crack.crosses(Vec2(0.5, 0.6), Vec2(0.7, 0.9)));   // same side
  EXPECT_FALSE(crack.crosses(Vec2(1.2, 0.4), Vec2(1.2, 0.6)));   // past the tip
  EXPECT_FALSE(crack.crosses(Vec2(-0.1, 0.4), Vec2(-0.3, 0.6)));  // past the other tip
  EXPECT_TRUE(crack.crosses(Vec2(0.75, 0.25), Vec2(1.25, 0.75)));  // through the tip itself (exact in binary)
}

TEST(Crack2, APointOnTheCrackIsOnTheNormalsSide) {
  // The crack runs left to right, so the + side (left of the direction) is above.
  const Crack<2> crack(Vec2(0, 0.5), Vec2(1, 0.5));
  const Vec2 on(0.5, 0.5);
  EXPECT_TRUE(crack.crosses(on, Vec2(0.5, 0.4)));
  EXPECT_FALSE(crack.crosses(on, Vec2(0.5, 0.6)));
  EXPECT_FALSE(crack.crosses(on, Vec2(0.6, 0.5)));  // along the crack
  // On the crack's line beyond the tip: nothing to cut.
  EXPECT_FALSE(crack.crosses(Vec2(1.5, 0.5), Vec2(1.5, 0.4)));
}

TEST(Crack3, RectangleAndPolygonCracks) {
  // The rectangle [0, 1] x [0, 2] in the plane z = 0.5.
  const Crack<3> rect = Crack<3>::rectangle(Vec3(0, 0, 0.5), Vec3(1, 0, 0), Vec3(0, 2, 0));
  EXPECT_TRUE(rect.crosses(Vec3(0.5, 1, 0.4), Vec3(0.5, 1, 0.6)));
  EXPECT_TRUE(rect.crosses(Vec3(0.1, 1.9, 0), Vec3(0.9, 0.1, 1)));
  EXPECT_FALSE(rect.crosses(Vec3(1.1, 1, 0.4), Vec3(1.1, 1, 0.6)));
  EXPECT_FALSE(rect.crosses(Vec3(0.5, 1, 0.6), Vec3(0.5, 1.5, 0.9)));
  EXPECT_TRUE(rect.crosses(Vec3(1, 1, 0.4), Vec3(1, 1, 0.6)));  // through an edge
  // A tilted triangle through (1, 0, 0), (0, 1, 0), (0, 0, 1).
  const Crack<3> tri({Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)});
  EXPECT_TRUE(tri.crosses(Vec3(0, 0, 0), Vec3(0.5, 0.5, 0.5)));
  EXPECT_FALSE(tri.crosses(Vec3(0, 0, 0), Vec3(0.2, 0.2, 0.2)));
  EXPECT_FALSE(tri.crosses(Vec3(2, -2, -1), Vec3(2, -2, 2)));  // crosses the plane outside the triangle
}

TEST(Cracks, VisibleUnlessACrackSeparates) {
  Cracks<2> cracks;
  EXPECT_TRUE(cracks.visible(Vec2(0, 0), Vec2(1, 1)));
  cracks.add(Crack<2>(Vec2(0, 0.5), Vec2(1, 0.5)));
  cracks.add(Crack<2>(Vec2(2, 0), Vec2(2, 1)));
  EXPECT_FALSE(cracks.visible(Vec2(0.5, 0.4), Vec2(0.5, 0.6)));
  EXPECT_FALSE(cracks.visible(Vec2(1.9, 0.2), Vec2(2.1, 0.2)));
  EXPECT_TRUE(cracks.visible(Vec2(1.5, 0.4), Vec2(1.5, 0.6)));
  EXPECT_TRUE(cracks.visible(Vec2(0.5, 0.6), Vec2(0.5, 0.6)));
  EXPECT_EQ(cracks.size(), 2u);
}

TEST(Cracks, Refusals) {
  using mfwave::testing::inputErrorKey;
  EXPECT_EQ(inputErrorKey([] { Crack<2>(Vec2(1, 1), Vec2(1, 1)); }), "crack");
  EXPECT_EQ(inputErrorKey([] { Crack<3>({Vec3(0, 0, 0), Vec3(1, 0, 0)}); }), "crack");
  EXPECT_EQ(inputErrorKey([] { Crack<3>({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0.1)}); }), "crack");
  EXPECT_EQ(inputErrorKey([] { Crack<3>::rectangle(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0)); }), "crack");
}
