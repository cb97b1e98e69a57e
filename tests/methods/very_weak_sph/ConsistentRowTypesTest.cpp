// Row-type reuse in the consistent correction (ConsistentCorrection.hpp, RowTypes.hpp): rows that
// are translates of each other share one decomposition, and the corrected operator and traction
// matrices equal those of row-by-row solves to 1e-13 relative (per row, against its largest entry).
// A perturbed block has no translates (no reuse expected); a lattice block is almost all translates.

#include "core/Material.hpp"
#include "methods/very_weak_sph/VeryWeakSph.hpp"
#include "particles/BoxFace.hpp"

#include "BlockFixture.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

using namespace mfwave;

namespace {

using RowMajor = Eigen::SparseMatrix<Real, Eigen::RowMajor, int>;

// Largest |a - b| over a row divided by the row's largest |b|; the patterns must be equal.
Real largestRowDifference(const SparseMatrix& a, const SparseMatrix& b) {
  const RowMajor ra(a), rb(b);
  EXPECT_EQ(ra.nonZeros(), rb.nonZeros());
  if (ra.nonZeros() != rb.nonZeros()) return 1;
  Real worst = 0;
  for (int row = 0; row < rb.outerSize(); ++row) {
    Real size = 0, difference = 0;
    RowMajor::InnerIterator ia(ra, row), ib(rb, row);
    for (; ia && ib; ++ia, ++ib) {
      EXPECT_EQ(ia.col(), ib.col());
      size = std::max(size, std::abs(ib.value()));
      difference = std::max(difference, std::abs(ia.value() - ib.value()));
    }
    if (size > 0) worst = std::max(worst, difference / size);
  }
  return worst;
}

// Assembles the consistent variant with and without reuse; returns the decompositions with reuse.
template <int D>
Index compareWithAndWithoutReuse(const char* title, const test::Block<D>& block) {
  VeryWeakSphOptions options;
  options.variant = VeryWeakSphVariant::Consistent;
  options.material = Material::fromLame(2, 1, 1);
  const VeryWeakSph<D> reused = assembleVeryWeakSph(block.particles, block.neighbours, block.kernel, options);
  options.reuseConsistentRowTypes = false;
  const VeryWeakSph<D> single = assembleVeryWeakSph(block.particles, block.neighbours, block.kernel, options);
  const Index n = block.particles.physicalCount();
  const Real operatorDifference = largestRowDifference(reused.data.operatorMatrix, single.data.operatorMatrix);
  const Real tractionDifference = largestRowDifference(reused.data.tractionMatrix, single.data.tractionMatrix);
  std::printf("%s: %lld rows, %lld decompositions with reuse; largest relative row difference: operator %.2e, "
              "traction %.2e; residual %.2e\n",
              title, static_cast<long long>(n), static_cast<long long>(reused.data.consistentDecompositions),
              operatorDifference, tractionDifference, reused.data.consistencyResidual);
  EXPECT_LE(operatorDifference, 1e-13);
  EXPECT_LE(tractionDifference, 1e-13);
  EXPECT_LT(reused.data.consistencyResidual, 1e-10);
  EXPECT_EQ(reused.data.consistentRowsSolved, n);
  EXPECT_EQ(single.data.consistentRowsSolved, n);
  EXPECT_EQ(single.data.consistentDecompositions, n);
  EXPECT_LT((Eigen::MatrixXd(reused.system.stiffness()) - Eigen::MatrixXd(single.system.stiffness())).norm(),
            1e-13 * Eigen::MatrixXd(single.system.stiffness()).norm());
  return reused.data.consistentDecompositions;
}

}  // namespace

TEST(ConsistentRowTypes, LatticeRowsShareDecompositionsAndMatchRowByRowSolves) {
  // 9 x 9 x 9 particles, h = dx, two ghost layers: per axis the rows at distance 0, 1 from either
  // face and the interior are the types, 5^3 = 125 in all.
  const test::Block<3> block(Vec3::Zero(), Vec3::Constant(4.0), 0.5, 2, 0.5);
  const Index decompositions = compareWithAndWithoutReuse("3-D lattice 9^3", block);
  EXPECT_LE(decompositions, 125);
  // dx = 0.3 is not a binary fraction: translated rows differ by round-off, and still share. Here
  // neighbours at exactly 2h (the support radius) fall in or out of the list by round-off, which
  // makes the rows at distance 2 from a face types of their own: 7^3.
  const test::Block<3> inexact(Vec3::Constant(0.1), Vec3::Constant(2.5), 0.3, 2, 0.3);
  EXPECT_LE(compareWithAndWithoutReuse("3-D lattice 9^3, dx = 0.3", inexact), 343);

  const test::Block<2> square(Vec2::Zero(), Vec2::Constant(4.0), 0.5, 2, 0.5);
  EXPECT_LE(compareWithAndWithoutReuse("2-D lattice 9^2", square), 25);
}

TEST(ConsistentRowTypes, PerturbedRowsAreAllSolvedOnTheirOwn) {
  test::Block<3> block(Vec3::Zero(), Vec3::Constant(2.5), 0.5, 2, 0.5);
  // Interior coordinates moved by up to 0.2 dx (face particles only within their faces).
  std::mt19937 random(17);
  for (Index a = 0; a < block.particles.physicalCount(); ++a) {
    Vec3 x = block.particles.position(a);
    const std::uint8_t mask = block.particles.faceMask[static_cast<std::size_t>(a)];
    for (int j = 0; j < 3; ++j) {
      const Real unit = 2.0 * static_cast<Real>(random()) / 4294967295.0 - 1.0;
      if ((mask & (faceBit(2 * j) | faceBit(2 * j + 1))) == 0) x[j] += 0.1 * unit;
    }
    block.particles.setPosition(a, x);
  }
  block.neighbours = buildNeighbourList(CellList<3>(block.particles, block.kernel.supportRadius()),
                                        block.particles.physicalCount());
  // Corners and edges stay translates of each other only where no interior particle moved in reach,
  // which on this small block is nowhere: every row is its own type.
  EXPECT_EQ(compareWithAndWithoutReuse("3-D perturbed 6^3", block), block.particles.physicalCount());
}
