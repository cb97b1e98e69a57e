// A rank's rows of a lattice operator, read from its local box, are bitwise the rows of the serial
// product: on any decomposition (1 to 6 ranks, every axis split), in 1-D, 2-D and 3-D, on 1 and 2
// threads. The serial product sends the middle of each lattice line through the vectorised runs
// (fused multiply-adds on AVX processors) and the ends row by row, so a split line must do the same
// node by node; this is what makes results independent of the rank count.

#include "decomposition/HaloPlan.hpp"
#include "decomposition/LocalStencils.hpp"

#include "core/Error.hpp"

#include "support/OnThreads.hpp"
#include "support/RandomVector.hpp"

#include <gtest/gtest.h>

#include <random>

namespace mfwave {
namespace {

// A random operator on the compact lattice of `types`: every node coupled (D x D blocks) to the
// nodes within `reach` along each axis that exist, so the rows near the faces read only inwards.
template <int D>
SparseMatrix randomCompactOperator(const LatticeRowTypes<D>& types, Index reach, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<Real> value(-1.0, 1.0);
  Box<D> compact;
  compact.hi = types.compactNodes();
  std::vector<Triplet> entries;
  compact.forEachNode([&](const std::array<Index, D>& row) {
    Box<D> around;
    for (std::size_t s = 0; s < static_cast<std::size_t>(D); ++s) {
      around.lo[s] = row[s] - reach;
      around.hi[s] = row[s] + reach + 1;
    }
    intersection(around, compact).forEachNode([&](const std::array<Index, D>& column) {
      for (int c = 0; c < D; ++c)
        for (int d = 0; d < D; ++d)
          entries.emplace_back(static_cast<int>(D * compact.localIndex(row) + c),
                               static_cast<int>(D * compact.localIndex(column) + d), value(random));
    });
  });
  SparseMatrix m(D * compact.count(), D * compact.count());
  m.setFromTriplets(entries.begin(), entries.end());
  return m;
}

// Every rank's owned rows against the serial product, bit for bit.
template <int D>
void expectRanksGiveTheSerialBits(const std::array<Index, D>& nodes, Index depth, int ranks, int threads = 1) {
  const LatticeRowTypes<D> types(nodes, depth);
  const LatticeStencils<D> stencils(types, randomCompactOperator<D>(types, depth, 11u + static_cast<unsigned>(ranks)));
  const Vector x = test::randomVector(D * types.nodeCount(), 5);
  Vector serial;
  stencils.multiply(x, serial);
  const BlockDecomposition<D> decomposition(types, ranks);
  Box<D> all;
  all.hi = nodes;
  for (int r = 0; r < ranks; ++r) {
    const HaloPlan<D> plan(decomposition, r, stencilReach(stencils));
    const LocalStencils<D> local(stencils, plan.owned(), plan.local());
    std::vector<Real> xLocal(static_cast<std::size_t>(D * plan.local().count()));
    plan.local().forEachNode([&](const std::array<Index, D>& node) {
      for (int c = 0; c < D; ++c)
        xLocal[static_cast<std::size_t>(D * plan.local().localIndex(node) + c)] = x[D * all.localIndex(node) + c];
    });
    const std::vector<Real> y = testing::onThreads(threads, [&] {
      std::vector<Real> out(static_cast<std::size_t>(D * plan.owned().count()));
      local.multiply(xLocal.data(), out.data());
      return out;
    });
    Index different = 0;
    plan.owned().forEachNode([&](const std::array<Index, D>& node) {
      for (int c = 0; c < D; ++c)
        if (y[static_cast<std::size_t>(D * plan.owned().localIndex(node) + c)] != serial[D * all.localIndex(node) + c]) ++different;
    });
    EXPECT_EQ(different, 0) << D << "-D, rank " << r << " of " << ranks;
  }
}

}  // namespace

TEST(LocalStencilsTest, EveryRanksRowsAreTheSerialRowsBitForBit) {
  for (int ranks = 1; ranks <= 6; ++ranks) {
    expectRanksGiveTheSerialBits<1>({61}, 2, ranks);
    expectRanksGiveTheSerialBits<2>({37, 19}, 2, ranks);
    expectRanksGiveTheSerialBits<3>({23, 11, 9}, 1, ranks);
    expectRanksGiveTheSerialBits<3>({19, 13, 11}, 2, ranks);
  }
  // Blocks narrower than the faces' depth, and lines long enough for several vector chunks.
  expectRanksGiveTheSerialBits<2>({9, 40}, 3, 4);
  expectRanksGiveTheSerialBits<1>({203}, 1, 3);
}

TEST(LocalStencilsTest, ThreadedLinesGiveTheSameBits) {
  // Above the size where the lines run on threads.
  expectRanksGiveTheSerialBits<3>({45, 30, 20}, 1, 2, 2);
}

TEST(LocalStencilsTest, AHaloShallowerThanTheStencilsIsRefused) {
  const LatticeRowTypes<2> types({20, 20}, 2);
  const LatticeStencils<2> stencils(types, randomCompactOperator<2>(types, 2, 3u));
  EXPECT_EQ(stencilReach(stencils), (std::array<Index, 2>{2, 2}));
  const BlockDecomposition<2> decomposition(types, 2);
  const HaloPlan<2> shallow(decomposition, 0, {1, 1});
  try {
    LocalStencils<2>(stencils, shallow.owned(), shallow.local());
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "halo");
  }
}

}  // namespace mfwave
