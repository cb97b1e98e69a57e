// The halo exchange under mpirun (ctest runs this program on 1, 2, 3 and 4 ranks): every rank
// fills the nodes it owns with a value that names the node, exchanges, and checks that its whole
// local box (its block and its halo) then holds each node's own value, in 1-D, 2-D and 3-D, for
// reaches 1 and 2 and with costly face rows that make the blocks unequal; and a lattice operator
// applied across the ranks gives the serial product's bits.
#include "decomposition/LocalStencils.hpp"
#include "decomposition/mpi/HaloExchange.hpp"
#include "decomposition/mpi/LineSums.hpp"
#include "lattice/LatticeSecondOrderSystem.hpp"

#include "core/Error.hpp"

#include "MpiTestSupport.hpp"
#include "support/RandomVector.hpp"

#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <random>
#include <limits>
#include <vector>

using namespace mfwave;
using test::worldRank;
using test::worldSize;

namespace {

// A value no two (node, component) pairs share.
template <int D>
Real nodeValue(const LatticeRowTypes<D>& types, const std::array<Index, D>& node, int component, int components) {
  Index linear = 0;
  for (int a = D - 1; a >= 0; --a) linear = linear * types.nodes()[static_cast<std::size_t>(a)] + node[static_cast<std::size_t>(a)];
  return static_cast<Real>(linear * components + component) + 0.25;
}

template <int D>
void expectExchangeFillsTheHalo(const LatticeRowTypes<D>& types, const std::array<Index, D>& reach, int components,
                                const std::vector<Real>& typeCost = {}) {
  const BlockDecomposition<D> decomposition(types, worldSize(), typeCost);
  HaloExchange<D> exchange(HaloPlan<D>(decomposition, worldRank(), reach), components, MPI_COMM_WORLD);
  const HaloPlan<D>& plan = exchange.plan();
  std::vector<Real> local(static_cast<std::size_t>(exchange.localSize()), std::numeric_limits<Real>::quiet_NaN());
  plan.owned().forEachNode([&](const std::array<Index, D>& node) {
    for (int c = 0; c < components; ++c)
      local[static_cast<std::size_t>(plan.local().localIndex(node) * components + c)] = nodeValue<D>(types, node, c, components);
  });
  exchange.exchange(local.data());
  Index wrong = 0;
  plan.local().forEachNode([&](const std::array<Index, D>& node) {
    for (int c = 0; c < components; ++c)
      if (local[static_cast<std::size_t>(plan.local().localIndex(node) * components + c)] != nodeValue<D>(types, node, c, components)) ++wrong;
  });
  EXPECT_EQ(wrong, 0) << "rank " << worldRank() << " of " << worldSize();
  // Every node is owned once over all ranks.
  long owned = static_cast<long>(plan.owned().count()), total = 0;
  MPI_Allreduce(&owned, &total, 1, MPI_LONG, MPI_SUM, MPI_COMM_WORLD);
  EXPECT_EQ(total, static_cast<long>(types.nodeCount()));
}

TEST(HaloExchangeMpiTest, FillsTheHaloWithTheOwnersValuesIn1d2d3d) {
  expectExchangeFillsTheHalo<1>(LatticeRowTypes<1>({57}, 2), {2}, 1);
  expectExchangeFillsTheHalo<2>(LatticeRowTypes<2>({31, 23}, 2), {2, 2}, 2);
  expectExchangeFillsTheHalo<3>(LatticeRowTypes<3>({17, 13, 11}, 1), {1, 1, 1}, 3);
  expectExchangeFillsTheHalo<3>(LatticeRowTypes<3>({14, 12, 10}, 2), {2, 2, 2}, 3);
}

TEST(HaloExchangeMpiTest, UnequalBlocksFromCostlyFaceRowsExchangeToo) {
  const LatticeRowTypes<2> types({40, 30}, 4);
  std::vector<Real> cost(static_cast<std::size_t>(types.typeCount()), 1.0);
  for (Index t = 0; t < types.typeCount(); ++t)
    if (t % types.compactNodes()[0] != types.depth()) cost[static_cast<std::size_t>(t)] = 4.0;
  expectExchangeFillsTheHalo<2>(types, {2, 2}, 2, cost);
}

TEST(HaloExchangeMpiTest, RepeatedExchangesWithStartAndFinishApart) {
  const LatticeRowTypes<3> types({16, 9, 7}, 1);
  const BlockDecomposition<3> decomposition(types, worldSize());
  HaloExchange<3> exchange(HaloPlan<3>(decomposition, worldRank(), {1, 1, 1}), 1, MPI_COMM_WORLD, 7);
  const HaloPlan<3>& plan = exchange.plan();
  std::vector<Real> local(static_cast<std::size_t>(exchange.localSize()), 0.0);
  for (int round = 1; round <= 3; ++round) {
    plan.owned().forEachNode([&](const std::array<Index, 3>& node) {
      local[static_cast<std::size_t>(plan.local().localIndex(node))] = round * nodeValue<3>(types, node, 0, 1);
    });
    exchange.start(local.data());
    exchange.finish(local.data());
    plan.local().forEachNode([&](const std::array<Index, 3>& node) {
      ASSERT_EQ(local[static_cast<std::size_t>(plan.local().localIndex(node))], round * nodeValue<3>(types, node, 0, 1));
    });
  }
  EXPECT_THROW(exchange.finish(local.data()), Error);
}

// A lattice operator applied across the ranks (each rank fills its own nodes, exchanges its halo,
// applies its rows) gives every row bitwise as the serial product on one process does.
// A 3-component operator on the compact lattice of `types`, coupling every node to the nodes
// within 2 along each axis.
SparseMatrix randomCompactOperator(const LatticeRowTypes<3>& types, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<Real> value(-1.0, 1.0);
  Box<3> compact;
  compact.hi = types.compactNodes();
  std::vector<Triplet> entries;
  compact.forEachNode([&](const std::array<Index, 3>& row) {
    Box<3> around;
    for (std::size_t s = 0; s < 3; ++s) {
      around.lo[s] = row[s] - 2;
      around.hi[s] = row[s] + 3;
    }
    intersection(around, compact).forEachNode([&](const std::array<Index, 3>& column) {
      for (int c = 0; c < 3; ++c)
        for (int d = 0; d < 3; ++d)
          entries.emplace_back(static_cast<int>(3 * compact.localIndex(row) + c),
                               static_cast<int>(3 * compact.localIndex(column) + d), value(random));
    });
  });
  SparseMatrix matrix(3 * compact.count(), 3 * compact.count());
  matrix.setFromTriplets(entries.begin(), entries.end());
  return matrix;
}

// This rank's local box filled from the whole lattice's x at the nodes it owns, NaN in its halo,
// then exchanged.
std::vector<Real> exchangedLocal(HaloExchange<3>& exchange, const LatticeRowTypes<3>& types, const Vector& x) {
  const HaloPlan<3>& plan = exchange.plan();
  Box<3> all;
  all.hi = types.nodes();
  std::vector<Real> local(static_cast<std::size_t>(exchange.localSize()), std::numeric_limits<Real>::quiet_NaN());
  plan.owned().forEachNode([&](const std::array<Index, 3>& node) {
    for (int c = 0; c < 3; ++c) local[static_cast<std::size_t>(3 * plan.local().localIndex(node) + c)] = x[3 * all.localIndex(node) + c];
  });
  exchange.exchange(local.data());
  return local;
}

}  // namespace

// A lattice operator applied across the ranks (each rank fills its own nodes, exchanges its halo,
// applies its rows) gives every row bitwise as the serial product on one process does.
TEST(HaloExchangeMpiTest, TheDistributedProductIsTheSerialProductBitForBit) {
  const LatticeRowTypes<3> types({29, 17, 13}, 2);
  const SparseMatrix matrix = randomCompactOperator(types, 17u);
  const LatticeStencils<3> stencils(types, matrix);
  const Vector x = test::randomVector(3 * types.nodeCount(), 9);
  Vector serial;
  stencils.multiply(x, serial);

  const BlockDecomposition<3> decomposition(types, worldSize());
  HaloExchange<3> exchange(HaloPlan<3>(decomposition, worldRank(), stencilReach(stencils)), 3, MPI_COMM_WORLD);
  const HaloPlan<3>& plan = exchange.plan();
  Box<3> all;
  all.hi = types.nodes();
  const std::vector<Real> local = exchangedLocal(exchange, types, x);
  const LocalStencils<3> rows(stencils, plan.owned(), plan.local());
  std::vector<Real> y(static_cast<std::size_t>(3 * plan.owned().count()));
  rows.multiply(local.data(), y.data());
  long different = 0;
  plan.owned().forEachNode([&](const std::array<Index, 3>& node) {
    for (int c = 0; c < 3; ++c)
      if (y[static_cast<std::size_t>(3 * plan.owned().localIndex(node) + c)] != serial[3 * all.localIndex(node) + c]) ++different;
  });
  MPI_Allreduce(MPI_IN_PLACE, &different, 1, MPI_LONG, MPI_SUM, MPI_COMM_WORLD);
  EXPECT_EQ(different, 0);
}

// The strain energy u . K u / 2 summed over the ranks: with x kept whole, each rank's line sums are
// the serial ones and sumInLatticeOrder adds them in the serial order, so every rank gets the
// serial system's figure bit for bit.
TEST(HaloExchangeMpiTest, AnEnergyOverTheRanksIsTheSerialEnergyBitForBit) {
  const LatticeRowTypes<3> types({23, 19, 14}, 2);
  const LatticeStencils<3> stiffness(types, randomCompactOperator(types, 23u));
  SparseMatrix identity(3 * types.compactNodes()[0] * types.compactNodes()[1] * types.compactNodes()[2],
                        3 * types.compactNodes()[0] * types.compactNodes()[1] * types.compactNodes()[2]);
  identity.setIdentity();
  const LatticeSecondOrderSystem<3> system(LatticeStencils<3>(types, identity), LatticeStencils<3>(), stiffness);
  const Vector u = test::randomVector(3 * types.nodeCount(), 4);
  const Real serial = system.strainEnergy(u);

  const BlockDecomposition<3> decomposition(types, worldSize(), {}, {false, true, true});
  ASSERT_EQ(decomposition.grid()[0], 1);
  HaloExchange<3> exchange(HaloPlan<3>(decomposition, worldRank(), stencilReach(stiffness)), 3, MPI_COMM_WORLD);
  const HaloPlan<3>& plan = exchange.plan();
  const std::vector<Real> local = exchangedLocal(exchange, types, u);
  const LocalStencils<3> rows(stiffness, plan.owned(), plan.local());
  std::vector<Real> ku(static_cast<std::size_t>(3 * plan.owned().count()));
  rows.multiply(local.data(), ku.data());
  // Per owned line, u . K u node by node along x, as the serial sum adds them.
  const Index nx = plan.owned().extent(0);
  std::vector<Real> lineSums(static_cast<std::size_t>(plan.owned().count() / nx), 0.0);
  plan.owned().forEachNode([&](const std::array<Index, 3>& node) {
    const Index k = plan.owned().localIndex(node);
    const Real* un = local.data() + 3 * plan.local().localIndex(node);
    Real s = 0;
    for (int c = 0; c < 3; ++c) s += un[c] * ku[static_cast<std::size_t>(3 * k + c)];
    lineSums[static_cast<std::size_t>(k / nx)] += s;
  });
  const Real distributed = 0.5 * sumInLatticeOrder(decomposition, worldRank(), lineSums, MPI_COMM_WORLD);
  EXPECT_EQ(distributed, serial) << "difference " << distributed - serial;
  EXPECT_GT(std::abs(serial), 0.0);
  // A decomposition that splits x cannot promise the serial order, and says so.
  if (worldSize() > 1) {
    const BlockDecomposition<3> slabs(LatticeRowTypes<3>({40, 5, 5}, 1), worldSize());
    ASSERT_GT(slabs.grid()[0], 1);
    EXPECT_THROW(sumInLatticeOrder(slabs, worldRank(), std::vector<Real>(1), MPI_COMM_WORLD), Error);
  }
}


// Sums over a lattice whose lines are cut along x: each x-piece goes on from the running sums of
// the piece before it (LineSums.hpp), so the total is the serial one bit for bit. The terms span
// 16 orders of magnitude and some are absent (-0.0), so any other order of addition (each piece
// from 0, say) misses, which the test checks of its own data.
TEST(HaloExchangeMpiTest, SumsOfLinesCutAlongXAreTheSerialSumsBitForBit) {
  const LatticeRowTypes<2> types({40, 6}, 1);
  const BlockDecomposition<2> decomposition(types, worldSize());  // every axis may be cut
  if (worldSize() > 1) {
    ASSERT_GT(decomposition.grid()[0], 1);
  }
  Box<2> all;
  all.hi = types.nodes();
  const int termsPerNode = 2;
  std::mt19937 random(7);
  std::uniform_real_distribution<Real> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-8, 8);
  std::vector<Real> terms(static_cast<std::size_t>(termsPerNode * all.count()));
  for (Real& t : terms) t = random() % 5 == 0 ? -0.0 : mantissa(random) * std::pow(10.0, exponent(random));
  // The serial order: each line along x from +0, absent terms not added, then the lines in order.
  Real serial = 0, piecesFromZero = 0;
  std::vector<Real> lineSums(static_cast<std::size_t>(all.lineCount()), 0.0);
  all.forEachNode([&](const std::array<Index, 2>& node) {
    for (int j = 0; j < termsPerNode; ++j) {
      const Real t = terms[static_cast<std::size_t>(termsPerNode * all.localIndex(node) + j)];
      if (!std::signbit(t) || t != 0) lineSums[static_cast<std::size_t>(node[1])] += t;
    }
  });
  for (Real s : lineSums) serial += s;
  // What adding each piece from 0 would give: the order the chain must not take.
  {
    for (Index y = 0; y < types.nodes()[1]; ++y) {
      Real line = 0;
      for (std::size_t k = 0; k + 1 < decomposition.cuts(0).size(); ++k) {
        Real piece = 0;
        for (Index x = decomposition.cuts(0)[k]; x < decomposition.cuts(0)[k + 1]; ++x)
          for (int j = 0; j < termsPerNode; ++j) piece += terms[static_cast<std::size_t>(termsPerNode * all.localIndex({x, y}) + j)];
        line += piece;
      }
      piecesFromZero += line;
    }
  }
  if (decomposition.grid()[0] > 1) {
    ASSERT_NE(piecesFromZero, serial) << "the test's terms do not tell the orders apart";
  }

  // This rank's block's terms, in its order.
  const Box<2> own = decomposition.block(worldRank());
  std::vector<Real> mine;
  own.forEachNode([&](const std::array<Index, 2>& node) {
    for (int j = 0; j < termsPerNode; ++j) mine.push_back(terms[static_cast<std::size_t>(termsPerNode * all.localIndex(node) + j)]);
  });
  const Real chained = sumNodeTermsInLatticeOrder(decomposition, worldRank(), mine, termsPerNode, MPI_COMM_WORLD);
  EXPECT_EQ(chained, serial) << "difference " << chained - serial;
  // The callers' form: the terms through a callable (absent ones not given).
  const Real given = sumInLatticeOrder<2>(decomposition, worldRank(), termsPerNode, [&](auto&& add) {
    for (Index k = 0; k < own.count(); ++k)
      for (int j = 0; j < termsPerNode; ++j) {
        const Real t = mine[static_cast<std::size_t>(termsPerNode * k + j)];
        if (!std::signbit(t) || t != 0) add(k, j, t);
      }
  }, MPI_COMM_WORLD);
  EXPECT_EQ(given, serial) << "difference " << given - serial;
  // A count of terms that does not match the block is refused.
  EXPECT_THROW(sumNodeTermsInLatticeOrder(decomposition, worldRank(), std::vector<Real>(1), termsPerNode, MPI_COMM_WORLD),
               Error);
}
