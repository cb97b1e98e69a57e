// Stencils read off a compact assembly give every row of the big lattice, and the vectorised runs
// give the per-node rows' bits.

#include "core/Error.hpp"
#include "lattice/LatticeStencils.hpp"

#include "support/OnThreads.hpp"
#include "support/RandomVector.hpp"

#include <gtest/gtest.h>

#include <random>

namespace mfwave {
namespace {

// A 2-D, 2-component operator on an nx x ny lattice whose rows depend on the distance to the faces
// up to 2 nodes: the Laplacian's 5-point stencil coupling the components, plus a face term (a
// different weight on the first two nodes from each face).
SparseMatrix faceOperator(Index nx, Index ny) {
  std::vector<Triplet> t;
  auto id = [&](Index i, Index j, int c) { return static_cast<int>(2 * (i + nx * j) + c); };
  auto weight = [](Index i, Index n) { return i == 0 || i == n - 1 ? 3.0 : (i == 1 || i == n - 2 ? 1.5 : 1.0); };
  for (Index j = 0; j < ny; ++j)
    for (Index i = 0; i < nx; ++i)
      for (int c = 0; c < 2; ++c) {
        const Real w = weight(i, nx) * (c + 1) + 0.25 * weight(j, ny);
        t.emplace_back(id(i, j, c), id(i, j, c), 4 * w);
        t.emplace_back(id(i, j, c), id(i, j, 1 - c), 0.5);
        if (i > 0) t.emplace_back(id(i, j, c), id(i - 1, j, c), -w);
        if (i + 1 < nx) t.emplace_back(id(i, j, c), id(i + 1, j, 1 - c), -0.3 * w);
        if (j > 0) t.emplace_back(id(i, j, c), id(i, j - 1, c), -1.0);
        if (j + 1 < ny) t.emplace_back(id(i, j, c), id(i, j + 1, c), -1.0 - 0.1 * c);
      }
  SparseMatrix m(2 * nx * ny, 2 * nx * ny);
  m.setFromTriplets(t.begin(), t.end());
  return m;
}

Vector randomVector(Index n) { return test::randomVector(n, 7); }

TEST(LatticeStencils, ReproduceTheBigLatticeFromTheCompactOneAtTheRightDepth) {
  const std::array<Index, 2> nodes{41, 23};
  const LatticeRowTypes<2> types(nodes, 2);
  const SparseMatrix compact = faceOperator(types.compactNodes()[0], types.compactNodes()[1]);
  const LatticeStencils<2> stencils(types, compact);
  EXPECT_EQ(stencils.typeCount(), 25);
  EXPECT_FALSE(stencils.blockDiagonal());
  const SparseMatrix big = faceOperator(nodes[0], nodes[1]);
  EXPECT_LE(stencils.mismatch(big), 1e-15);
  const Vector x = randomVector(big.cols());
  Vector y;
  stencils.multiply(x, y);
  EXPECT_LE((y - big * x).cwiseAbs().maxCoeff(), 1e-13);
  Vector sums = Vector::Zero(big.rows());
  for (int k = 0; k < big.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(big, k); it; ++it) sums[it.row()] += std::abs(it.value());
  EXPECT_LE((stencils.absoluteRowSums() - sums).cwiseAbs().maxCoeff(), 1e-13);

  // one depth too shallow: the rows at distance 1 from a face are not the interior's
  const LatticeRowTypes<2> shallow(nodes, 1);
  const LatticeStencils<2> wrong(shallow, faceOperator(shallow.compactNodes()[0], shallow.compactNodes()[1]));
  EXPECT_GT(wrong.mismatch(big), 0.1);
}

// The runs (the middle of each line, vectorised) add the per-node rows' terms in the same order (to
// the rounding of fused multiply-adds on AVX processors), and a product is bitwise the same on 1
// and 2 threads.
TEST(LatticeStencils, RunsGiveThePerNodeRowsBitsOnAnyThreadCount) {
  const std::array<Index, 2> nodes{157, 140};  // above the size where the product runs threaded
  const LatticeRowTypes<2> types(nodes, 2);
  const LatticeStencils<2> stencils(types, faceOperator(types.compactNodes()[0], types.compactNodes()[1]));
  const Vector x = randomVector(2 * nodes[0] * nodes[1]);
  Vector perNode(x.size());
  for (Index p = 0; p < types.nodeCount(); ++p)
    stencils.rowProduct(types.typeOf(types.node(p)), p, x.data(), perNode.data() + 2 * p);
  const auto product = [&] {
    Vector y;
    stencils.multiply(x, y);
    return y;
  };
  const Vector one = testing::onThreads(1, product), two = testing::onThreads(2, product);
  EXPECT_LE((one - perNode).cwiseAbs().maxCoeff(), 1e-14 * perNode.cwiseAbs().maxCoeff());
  EXPECT_EQ((one - two).cwiseAbs().maxCoeff(), 0.0) << "1 against 2 threads";
}

TEST(LatticeStencils, MoveToAnotherLatticeOfTheSameDepth) {
  const LatticeRowTypes<2> types(std::array<Index, 2>{30, 30}, 2);
  const LatticeStencils<2> stencils(types, faceOperator(5, 5));
  const LatticeStencils<2> moved = stencils.on(types.on({12, 9}));
  EXPECT_LE(moved.mismatch(faceOperator(12, 9)), 1e-15);
  EXPECT_THROW(stencils.on(LatticeRowTypes<2>(std::array<Index, 2>{30, 30}, 3)), InputError);
  EXPECT_THROW(LatticeStencils<2>(types, faceOperator(6, 5)), InputError);  // not the compact lattice
}

}  // namespace
}  // namespace mfwave
