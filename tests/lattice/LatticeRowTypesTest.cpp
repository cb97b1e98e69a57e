// Row types of a box lattice: a node's type is where it sits against the faces, up to the depth.

#include "core/Error.hpp"
#include "lattice/LatticeRowTypes.hpp"

#include <gtest/gtest.h>

namespace mfwave {
namespace {

TEST(LatticeRowTypes, MapsEveryNodeToTheCompactNodeThatSitsTheSameWay) {
  const LatticeRowTypes<1> types(std::array<Index, 1>{10}, 2);
  EXPECT_EQ(types.compactNodes()[0], 5);
  EXPECT_EQ(types.typeCount(), 5);
  // distance 0 and 1 from the lower face, interior, distance 1 and 0 from the upper face
  const Index expected[10] = {0, 1, 2, 2, 2, 2, 2, 2, 3, 4};
  for (Index i = 0; i < 10; ++i) EXPECT_EQ(types.compactIndex(0, i), expected[i]) << "node " << i;
}

TEST(LatticeRowTypes, ShortAxesKeepEveryNode) {
  const LatticeRowTypes<3> types(std::array<Index, 3>{4, 9, 2}, 2);
  EXPECT_EQ(types.compactNodes(), (std::array<Index, 3>{4, 5, 2}));
  EXPECT_EQ(types.typeCount(), 40);
  for (Index i = 0; i < 4; ++i) EXPECT_EQ(types.compactIndex(0, i), i);
  EXPECT_EQ(types.compactIndex(1, 6), 2);
  EXPECT_EQ(types.compactIndex(1, 7), 3);
  // the type is the compact node's linear index, x fastest; node() inverts the linear index
  EXPECT_EQ(types.typeOf({3, 8, 1}), 3 + 4 * (4 + 5 * 1));
  EXPECT_EQ(types.node(3 + 4 * (8 + 9 * 1)), (std::array<Index, 3>{3, 8, 1}));
}

TEST(LatticeRowTypes, RefusesEmptyAxesAndZeroDepth) {
  EXPECT_THROW(LatticeRowTypes<2>(std::array<Index, 2>{3, 0}, 1), InputError);
  EXPECT_THROW(LatticeRowTypes<2>(std::array<Index, 2>{3, 3}, 0), InputError);
}

}  // namespace
}  // namespace mfwave
