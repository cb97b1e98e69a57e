// CSG: signs and distances of union, intersection and difference; the active operand's normal
// (reversed for a subtracted one) and name; bounds; a half-space made finite by a box.

#include "geometry/Ball.hpp"
#include "geometry/BoxSolid.hpp"
#include "geometry/Csg.hpp"
#include "geometry/HalfSpace.hpp"
#include "support/InputErrorKey.hpp"

#include <gtest/gtest.h>

#include <memory>

using namespace mfwave;

TEST(Csg, BoxWithAHole) {
  const auto block = std::make_shared<BoxSolid<3>>(Vec3(-2, -2, -1), Vec3(2, 2, 1), "block");
  const auto hole = std::make_shared<Ball<3>>(Vec3(0, 0, 0), 0.5, "hole");
  const SolidPtr<3> solid = subtract<3>(block, hole);
  EXPECT_FALSE(solid->inside(Vec3(0, 0, 0)));
  EXPECT_TRUE(solid->inside(Vec3(1, 0, 0)));
  EXPECT_DOUBLE_EQ(solid->signedDistance(Vec3(0, 0, 0)), 0.5);
  EXPECT_DOUBLE_EQ(solid->signedDistance(Vec3(0.7, 0, 0)), -0.2);
  EXPECT_DOUBLE_EQ(solid->signedDistance(Vec3(1.5, 0, 0.8)), -0.2);
  EXPECT_EQ(solid->surfaceName(Vec3(0.6, 0, 0)), "hole.surface");
  EXPECT_EQ(solid->surfaceName(Vec3(1.5, 0, 0.9)), "block.+z");
  // The hole's normal points out of the solid: into the hole, towards its centre.
  EXPECT_NEAR((solid->normal(Vec3(0.6, 0, 0)) - Vec3(-1, 0, 0)).norm(), 0, 1e-15);
  EXPECT_EQ(solid->normal(Vec3(1.5, 0, 0.9)), Vec3(0, 0, 1));
  EXPECT_EQ(solid->bounds().lower, Vec3(-2, -2, -1));
}

TEST(Csg, UnionAndIntersectionOfTwoDiscs) {
  const auto left = std::make_shared<Ball<2>>(Vec2(-0.5, 0), 1.0, "left");
  const auto right = std::make_shared<Ball<2>>(Vec2(0.5, 0), 1.0, "right");
  const SolidPtr<2> both = unite<2>(left, right), lens = intersect<2>(left, right);
  EXPECT_TRUE(both->inside(Vec2(-1.4, 0)));
  EXPECT_FALSE(lens->inside(Vec2(-1.4, 0)));
  EXPECT_TRUE(lens->inside(Vec2(0, 0.8)));
  EXPECT_DOUBLE_EQ(both->signedDistance(Vec2(2, 0)), 0.5);
  EXPECT_DOUBLE_EQ(lens->signedDistance(Vec2(0, 0)), -0.5);
  EXPECT_EQ(both->surfaceName(Vec2(-1.6, 0)), "left.surface");
  EXPECT_EQ(both->surfaceName(Vec2(1.6, 0)), "right.surface");
  // On the lens's left flank the right disc's surface is the active one.
  EXPECT_EQ(lens->surfaceName(Vec2(-0.45, 0)), "right.surface");
  EXPECT_NEAR((lens->normal(Vec2(-0.45, 0)) - Vec2(-1, 0)).norm(), 0, 1e-15);
  EXPECT_EQ(both->bounds().lower, Vec2(-1.5, -1));
  EXPECT_EQ(lens->bounds().upper, Vec2(0.5, 1));
  // Nesting: the union of three, one of them a union itself.
  const auto third = std::make_shared<Ball<2>>(Vec2(0, 3), 0.5);
  const SolidUnion<2> three({both, third});
  EXPECT_TRUE(three.inside(Vec2(0, 3.4)));
  EXPECT_EQ(three.surfaceName(Vec2(0, 3.6)), "surface");
}

TEST(Csg, AHalfSpaceCutByABoxIsFinite) {
  const auto box = std::make_shared<BoxSolid<2>>(Vec2(0, 0), Vec2(1, 1));
  const auto below = std::make_shared<HalfSpace<2>>(Vec2(0, 1), Vec2(1, 1), "slope");
  const SolidPtr<2> triangle = intersect<2>(below, box);
  EXPECT_TRUE(triangle->bounds().finite());
  EXPECT_TRUE(triangle->inside(Vec2(0.2, 0.2)));
  EXPECT_FALSE(triangle->inside(Vec2(0.8, 0.8)));
  EXPECT_EQ(triangle->surfaceName(Vec2(0.45, 0.45)), "slope.plane");
}

TEST(Csg, RefusesMissingOperands) {
  using mfwave::testing::inputErrorKey;
  EXPECT_EQ(inputErrorKey([] { SolidUnion<2>({}); }), "union");
  EXPECT_EQ(inputErrorKey([] { SolidIntersection<3>({nullptr}); }), "intersection");
  EXPECT_EQ(inputErrorKey([] { SolidDifference<2>(nullptr, std::make_shared<Ball<2>>(Vec2(0, 0), 1.0)); }), "difference");
}
