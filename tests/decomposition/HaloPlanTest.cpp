#include "decomposition/HaloPlan.hpp"

#include "core/Error.hpp"

#include <gtest/gtest.h>

#include <map>
#include <vector>

using namespace mfwave;

namespace {

// What p sends q is what q receives from p, and each rank's halo (its local box minus its block)
// is covered exactly once by its receives, each from the node's owner.
template <int D>
void expectConsistentPlans(const BlockDecomposition<D>& d, const std::array<Index, D>& reach) {
  std::vector<HaloPlan<D>> plans;
  for (int r = 0; r < d.ranks(); ++r) plans.emplace_back(d, r, reach);
  for (int p = 0; p < d.ranks(); ++p) {
    std::map<int, Box<D>> sent;
    for (const auto& m : plans[static_cast<std::size_t>(p)].sends()) sent[m.rank] = m.nodes;
    for (int q = 0; q < d.ranks(); ++q) {
      if (q == p) continue;
      const HaloMessage<D>* received = nullptr;
      for (const auto& m : plans[static_cast<std::size_t>(q)].receives())
        if (m.rank == p) received = &m;
      if (received == nullptr) {
        EXPECT_EQ(sent.count(q), 0u) << p << " -> " << q;
      } else {
        ASSERT_EQ(sent.count(q), 1u) << p << " -> " << q;
        EXPECT_EQ(sent[q], received->nodes);
      }
    }
    const HaloPlan<D>& plan = plans[static_cast<std::size_t>(p)];
    std::vector<int> covered(static_cast<std::size_t>(plan.local().count()), 0);
    for (const auto& m : plan.receives())
      m.nodes.forEachNode([&](const std::array<Index, D>& node) {
        ++covered[static_cast<std::size_t>(plan.local().localIndex(node))];
        EXPECT_EQ(d.owner(node), m.rank);
      });
    Index halo = 0;
    plan.local().forEachNode([&](const std::array<Index, D>& node) {
      const int times = covered[static_cast<std::size_t>(plan.local().localIndex(node))];
      if (plan.owned().contains(node)) {
        EXPECT_EQ(times, 0);
      } else {
        EXPECT_EQ(times, 1);
        ++halo;
      }
    });
    EXPECT_EQ(halo, plan.haloNodes());
  }
}

}  // namespace

TEST(HaloPlanTest, SendsMatchReceivesAndCoverTheHaloOnce) {
  for (int ranks : {1, 2, 3, 4, 6, 8}) {
    expectConsistentPlans(BlockDecomposition<1>(LatticeRowTypes<1>({40}, 2), ranks), {2});
    expectConsistentPlans(BlockDecomposition<2>(LatticeRowTypes<2>({20, 14}, 2), ranks), {2, 2});
    expectConsistentPlans(BlockDecomposition<3>(LatticeRowTypes<3>({12, 10, 8}, 1), ranks), {1, 1, 1});
  }
  // A reach deeper than a block: messages come from beyond the nearest neighbour.
  expectConsistentPlans(BlockDecomposition<1>(LatticeRowTypes<1>({12}, 1), 6), {3});
}

TEST(HaloPlanTest, TwoSlabsExchangeReachDeepFaces) {
  const BlockDecomposition<3> d(LatticeRowTypes<3>({40, 10, 10}, 1), 2);
  const HaloPlan<3> plan(d, 0, {2, 2, 2});
  EXPECT_EQ(plan.owned().hi[0], 20);
  EXPECT_EQ(plan.local().hi[0], 22);
  EXPECT_EQ(plan.haloNodes(), 2 * 10 * 10);
  EXPECT_EQ(plan.sentNodes(), 2 * 10 * 10);
  ASSERT_EQ(plan.sends().size(), 1u);
  EXPECT_EQ(plan.sends()[0].rank, 1);
  EXPECT_EQ(plan.sends()[0].nodes.lo[0], 18);
}

TEST(HaloPlanTest, BadInputNamesTheKey) {
  const BlockDecomposition<2> d(LatticeRowTypes<2>({8, 8}, 1), 2);
  try {
    HaloPlan<2>(d, 2, {1, 1});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "rank");
  }
  try {
    HaloPlan<2>(d, 0, {1, -1});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "reach");
  }
}
