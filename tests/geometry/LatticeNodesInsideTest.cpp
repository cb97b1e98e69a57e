// Lattice nodes inside a solid: a box whose faces run through nodes keeps them, a disc keeps the
// nodes within its radius, the count of a ball approaches its volume over dx^3.

#include "geometry/Ball.hpp"
#include "geometry/BoxSolid.hpp"
#include "geometry/LatticeNodesInside.hpp"
#include "support/InputErrorKey.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace mfwave;

TEST(LatticeNodesInside, BoxFacesThroughNodesKeepThem) {
  const BoxSolid<3> box(Vec3(0, 0, 0), Vec3(1, 0.3, 0.7));
  const InsideNodes<3> nodes = latticeNodesInside<3>(box, 0.1, Vec3(0, 0, 0));
  EXPECT_EQ(nodes.size(), 11 * 4 * 8);
  EXPECT_EQ(nodes.node.front(), (std::array<Index, 3>{0, 0, 0}));
  EXPECT_EQ(nodes.node.back(), (std::array<Index, 3>{10, 3, 7}));
  EXPECT_NEAR((nodes.position.back() - Vec3(1, 0.3, 0.7)).norm(), 0, 1e-15);
  EXPECT_EQ(nodes.node[1], (std::array<Index, 3>{1, 0, 0}));  // x fastest
}

TEST(LatticeNodesInside, DiscAndBall) {
  const Ball<2> disc(Vec2(0, 0), 1.0);
  const InsideNodes<2> nodes = latticeNodesInside<2>(disc, 0.5, Vec2(0, 0));
  EXPECT_EQ(nodes.size(), 13);  // (0,0), 4 at 0.5, 4 at 1.0, 4 at (0.5, 0.5)
  for (const Vec2& x : nodes.position) EXPECT_LE(x.norm(), 1.0 + 1e-12);
  const Ball<3> ball(Vec3(0.01, 0.02, 0.03), 1.0);
  const Real dx = 0.05;
  const InsideNodes<3> many = latticeNodesInside<3>(ball, dx, Vec3(0, 0, 0));
  EXPECT_NEAR(static_cast<Real>(many.size()) * dx * dx * dx, 4 * kPi / 3, 0.01 * 4 * kPi / 3);
  EXPECT_EQ(mfwave::testing::inputErrorKey([&] { latticeNodesInside<2>(disc, -1, Vec2(0, 0)); }), "spacing");
}
