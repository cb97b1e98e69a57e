#include "lattice/Box.hpp"

#include <gtest/gtest.h>

using namespace mfwave;

TEST(BoxTest, WalksItsNodesXFastestInItsOwnNumbering) {
  Box<3> box;
  box.lo = {1, 2, 3};
  box.hi = {4, 4, 5};
  EXPECT_EQ(box.count(), 3 * 2 * 2);
  Index k = 0;
  box.forEachNode([&](const std::array<Index, 3>& node) {
    EXPECT_EQ(box.localIndex(node), k);
    EXPECT_EQ(box.node(k), node);  // the numbering's inverse
    EXPECT_TRUE(box.contains(node));
    ++k;
  });
  EXPECT_EQ(k, box.count());
}

TEST(BoxTest, IntersectionsAndGrowthClipToTheLattice) {
  Box<2> a, b;
  a.lo = {0, 0};
  a.hi = {5, 5};
  b.lo = {3, 6};
  b.hi = {8, 9};
  EXPECT_TRUE(intersection(a, b).empty());
  EXPECT_EQ(intersection(a, b).count(), 0);
  const Box<2> g = grown(b, {2, 2}, {7, 10});
  EXPECT_EQ(g.lo, (std::array<Index, 2>{1, 4}));
  EXPECT_EQ(g.hi, (std::array<Index, 2>{7, 10}));
  EXPECT_EQ(intersection(a, g).count(), 4 * 1);
}
