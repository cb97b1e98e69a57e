#include "decomposition/BlockDecomposition.hpp"

#include "core/Error.hpp"

#include <gtest/gtest.h>

#include <vector>

using namespace mfwave;

namespace {

// Every node owned by exactly one rank, and owner() agrees with block().
template <int D>
void expectPartition(const BlockDecomposition<D>& decomposition) {
  Box<D> all;
  all.hi = decomposition.nodes();
  std::vector<int> owners(static_cast<std::size_t>(all.count()), -1);
  Index owned = 0;
  for (int r = 0; r < decomposition.ranks(); ++r) {
    const Box<D> block = decomposition.block(r);
    ASSERT_FALSE(block.empty()) << "rank " << r;
    owned += block.count();
    block.forEachNode([&](const std::array<Index, D>& node) {
      int& owner = owners[static_cast<std::size_t>(all.localIndex(node))];
      EXPECT_EQ(owner, -1) << "a node owned twice";
      owner = r;
      EXPECT_EQ(decomposition.owner(node), r);
    });
  }
  EXPECT_EQ(owned, all.count());
}

}  // namespace

TEST(BlockDecompositionTest, TheBlocksPartitionTheLatticeForEveryRankCount) {
  for (int ranks = 1; ranks <= 12; ++ranks) {
    expectPartition(BlockDecomposition<1>(LatticeRowTypes<1>({37}, 2), ranks));
    expectPartition(BlockDecomposition<2>(LatticeRowTypes<2>({23, 17}, 2), ranks));
    expectPartition(BlockDecomposition<3>(LatticeRowTypes<3>({13, 11, 9}, 2), ranks));
  }
}

TEST(BlockDecompositionTest, TheGridCutsTheLongAxesFirst) {
  // 4 ranks on a 400 x 100 x 100 box: four slabs across x (3 faces of 100 x 100 nodes, 3e4) beat
  // a 2 x 2 grid in x and y (one face of 100 x 100 and one of 400 x 100, 5e4).
  const BlockDecomposition<3> slabs(LatticeRowTypes<3>({400, 100, 100}, 1), 4);
  EXPECT_EQ(slabs.grid(), (std::array<int, 3>{4, 1, 1}));
  EXPECT_EQ(slabs.interfaceNodes(), 3 * 100 * 100);
  // 8 ranks on a cube: 2 x 2 x 2.
  const BlockDecomposition<3> cube(LatticeRowTypes<3>({100, 100, 100}, 1), 8);
  EXPECT_EQ(cube.grid(), (std::array<int, 3>{2, 2, 2}));
  EXPECT_EQ(cube.interfaceNodes(), 3 * 100 * 100);
}

TEST(BlockDecompositionTest, AxesKeptWholeAreNotCut) {
  // On a cube 8 ranks would be 2 x 2 x 2; with x whole, every rank owns whole lattice lines.
  const BlockDecomposition<3> lines(LatticeRowTypes<3>({100, 100, 100}, 1), 8, {}, {false, true, true});
  EXPECT_EQ(lines.grid()[0], 1);
  EXPECT_EQ(lines.grid()[1] * lines.grid()[2], 8);
  for (int r = 0; r < 8; ++r) EXPECT_EQ(lines.block(r).extent(0), 100);
  expectPartition(lines);
  // Nothing left to cut: a clear error.
  EXPECT_THROW(BlockDecomposition<2>(LatticeRowTypes<2>({50, 1}, 1), 2, {}, {false, true}), InputError);
}

TEST(BlockDecompositionTest, FitsSaysWhetherTheAxesThatMayBeCutTakeTheRanks) {
  // y alone takes 4 ranks on 100 x 5, not 6; x and y together take 6 (and 500, one node each).
  EXPECT_TRUE(BlockDecomposition<2>::fits({100, 5}, 4, {false, true}));
  EXPECT_FALSE(BlockDecomposition<2>::fits({100, 5}, 6, {false, true}));
  EXPECT_TRUE(BlockDecomposition<2>::fits({100, 5}, 6, {true, true}));
  EXPECT_TRUE(BlockDecomposition<2>::fits({100, 5}, 500, {true, true}));
  EXPECT_FALSE(BlockDecomposition<2>::fits({100, 5}, 501, {true, true}));
  // 1-D with x whole takes one rank only; fits never throws.
  EXPECT_TRUE(BlockDecomposition<1>::fits({41}, 1, {false}));
  EXPECT_FALSE(BlockDecomposition<1>::fits({41}, 2, {false}));
  EXPECT_FALSE(BlockDecomposition<1>::fits({41}, 0, {true}));
}

TEST(BlockDecompositionTest, EqualCostsGiveBlocksWithinOneNodePlaneOfEachOther) {
  const BlockDecomposition<2> d(LatticeRowTypes<2>({1000, 10}, 3), 3);
  ASSERT_EQ(d.grid(), (std::array<int, 2>{3, 1}));
  EXPECT_EQ(d.cuts(0), (std::vector<Index>{0, 333, 667, 1000}));
  EXPECT_NEAR(d.imbalance(), 334.0 / (1000.0 / 3.0), 1e-12);
}

TEST(BlockDecompositionTest, CostlyFaceRowsGiveTheirBlocksFewerNodes) {
  // Rows within 10 nodes of either x face cost 5 (say, absorbing dashpots): 2 x 10 x 5 + 80 = 180
  // units along x, 60 per rank, so the outer blocks hold 10 face nodes + 10 interior ones.
  const LatticeRowTypes<1> types({100}, 10);
  std::vector<Real> cost(static_cast<std::size_t>(types.typeCount()), 1.0);
  for (Index c = 0; c < types.typeCount(); ++c)
    if (c != types.depth()) cost[static_cast<std::size_t>(c)] = 5.0;
  const BlockDecomposition<1> d(types, 3, cost);
  EXPECT_EQ(d.cuts(0), (std::vector<Index>{0, 20, 80, 100}));
  EXPECT_DOUBLE_EQ(d.cost(0), 60.0);
  EXPECT_DOUBLE_EQ(d.cost(1), 60.0);
  EXPECT_DOUBLE_EQ(d.cost(2), 60.0);
  EXPECT_DOUBLE_EQ(d.imbalance(), 1.0);
  // Without the costs the same lattice splits by node count.
  EXPECT_EQ(BlockDecomposition<1>(types, 3).cuts(0), (std::vector<Index>{0, 33, 67, 100}));
}

TEST(BlockDecompositionTest, BlockCostsAddUpToTheLatticeCostComputedNodeByNode) {
  const LatticeRowTypes<3> types({30, 20, 12}, 2);
  std::vector<Real> cost(static_cast<std::size_t>(types.typeCount()));
  for (std::size_t t = 0; t < cost.size(); ++t) cost[t] = 1.0 + 0.37 * static_cast<Real>(t % 7);
  const BlockDecomposition<3> d(types, 6, cost);
  Real direct = 0;
  Box<3> all;
  all.hi = types.nodes();
  all.forEachNode([&](const std::array<Index, 3>& node) { direct += cost[static_cast<std::size_t>(types.typeOf(node))]; });
  Real summed = 0;
  for (int r = 0; r < d.ranks(); ++r) summed += d.cost(r);
  EXPECT_NEAR(summed, direct, 1e-9 * direct);
  EXPECT_LT(d.imbalance(), 1.15);
}

TEST(BlockDecompositionTest, BadInputNamesTheKey) {
  const LatticeRowTypes<2> types({4, 3}, 1);
  try {
    BlockDecomposition<2>(types, 0);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "ranks");
  }
  try {
    BlockDecomposition<2>(types, 13);  // 13 is prime and longer than both axes
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "ranks");
    EXPECT_NE(std::string(e.what()).find("4 x 3"), std::string::npos) << e.what();
  }
  try {
    BlockDecomposition<2>(types, 2, {1.0, 2.0});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "cost");
  }
}
