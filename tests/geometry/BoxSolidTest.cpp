// Box: exact signed distance inside, outside and beyond a corner; face normals and names, with and
// without a user name; bounds; refusals.

#include "geometry/BoxSolid.hpp"
#include "support/InputErrorKey.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace mfwave;

TEST(BoxSolid, SignedDistanceIsExact) {
  const BoxSolid<3> box(Vec3(0, 0, 0), Vec3(2, 1, 1));
  EXPECT_DOUBLE_EQ(box.signedDistance(Vec3(1, 0.5, 0.5)), -0.5);   // centre: nearest faces y, z
  EXPECT_NEAR(box.signedDistance(Vec3(1.9, 0.5, 0.5)), -0.1, 1e-15);  // near +x
  EXPECT_DOUBLE_EQ(box.signedDistance(Vec3(2.5, 0.5, 0.5)), 0.5);   // beyond +x
  EXPECT_DOUBLE_EQ(box.signedDistance(Vec3(2.3, 1.4, 0.5)), 0.5);   // beyond the +x +y edge: 3-4-5
  EXPECT_NEAR(box.signedDistance(Vec3(-1, -1, -1)), std::sqrt(3.0), 1e-15);
  EXPECT_DOUBLE_EQ(box.signedDistance(Vec3(2, 0.5, 0.5)), 0.0);
  EXPECT_TRUE(box.inside(Vec3(2, 0.5, 0.5)));
  EXPECT_FALSE(box.inside(Vec3(2.001, 0.5, 0.5)));
}

TEST(BoxSolid, FacesHaveNamesAndOutwardNormals) {
  const BoxSolid<3> box(Vec3(0, 0, 0), Vec3(2, 1, 1));
  EXPECT_EQ(box.surfaceName(Vec3(0.1, 0.5, 0.5)), "-x");
  EXPECT_EQ(box.surfaceName(Vec3(1.95, 0.5, 0.5)), "+x");
  EXPECT_EQ(box.surfaceName(Vec3(1, 0.02, 0.5)), "-y");
  EXPECT_EQ(box.surfaceName(Vec3(1, 0.5, 1.3)), "+z");
  EXPECT_EQ(box.normal(Vec3(1, 0.5, 1.3)), Vec3(0, 0, 1));
  EXPECT_EQ(box.normal(Vec3(1, 0.02, 0.5)), Vec3(0, -1, 0));
  // Beyond an edge the face x lies further out of is the one that counts.
  EXPECT_EQ(box.surfaceName(Vec3(2.3, 1.1, 0.5)), "+x");
  const BoxSolid<2> block(Vec2(-1, -1), Vec2(1, 0), "block");
  EXPECT_EQ(block.surfaceName(Vec2(0, -0.01)), "block.+y");
  EXPECT_EQ(block.surfaceName(Vec2(-0.98, -0.5)), "block.-x");
  EXPECT_EQ(block.normal(Vec2(-0.98, -0.5)), Vec2(-1, 0));
}

TEST(BoxSolid, BoundsAreTheBox) {
  const BoxSolid<2> box(Vec2(-1, 2), Vec2(3, 5));
  EXPECT_EQ(box.bounds().lower, Vec2(-1, 2));
  EXPECT_EQ(box.bounds().upper, Vec2(3, 5));
}

TEST(BoxSolid, RefusesAnEmptyBoxAndABadName) {
  using mfwave::testing::inputErrorKey;
  EXPECT_EQ(inputErrorKey([] { BoxSolid<2>(Vec2(0, 0), Vec2(1, 0)); }), "box.upper");
  EXPECT_EQ(inputErrorKey([] { BoxSolid<3>(Vec3(0, 0, 0), Vec3(1, 1, -1), "slab"); }), "slab.upper");
  EXPECT_EQ(inputErrorKey([] { BoxSolid<2>(Vec2(0, 0), Vec2(1, NAN)); }), "box.upper");
  EXPECT_EQ(inputErrorKey([] { BoxSolid<2>(Vec2(0, 0), Vec2(1, 1), "a.b"); }), "box.name");
}
