// NeighbourList: equality with brute force on random clouds (1-3 D, several radii, moved
// particles, duplicates), the strict-distance rule on a lattice, exact mean counts, ghost
// rows, and independence from the OpenMP thread count.

#include "support/InputErrorKey.hpp"
#include "BruteForce.hpp"

#include "core/Error.hpp"
#include "neighbours/CellList.hpp"
#include "neighbours/NeighbourList.hpp"
#include "particles/BoxFace.hpp"
#include "particles/GhostLayers.hpp"
#include "particles/Lattice.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <random>
#include <string>

using namespace mfwave;
using namespace mfwave::testing;

namespace {

// Compares two lists row by row and reports the first difference (not two huge vectors).
::testing::AssertionResult sameLists(const NeighbourList& actual, const NeighbourList& expected) {
  if (actual.rowCount() != expected.rowCount()) {
    return ::testing::AssertionFailure() << "rows " << actual.rowCount() << " vs " << expected.rowCount();
  }
  for (Index i = 0; i < expected.rowCount(); ++i) {
    const std::vector<Index> a(actual.row(i).begin(), actual.row(i).end());
    const std::vector<Index> e(expected.row(i).begin(), expected.row(i).end());
    if (a != e || actual.offsets[static_cast<std::size_t>(i)] != expected.offsets[static_cast<std::size_t>(i)]) {
      auto failure = ::testing::AssertionFailure() << "row " << i << ": got";
      for (Index j : a) failure << ' ' << j;
      failure << "; expected";
      for (Index j : e) failure << ' ' << j;
      return failure;
    }
  }
  if (actual.offsets.back() != expected.offsets.back()) return ::testing::AssertionFailure() << "last offset";
  return ::testing::AssertionSuccess();
}

template <int D>
void expectMatchesBruteForce(const Coordinates<D>& x, Real radius, Real minimumMean) {
  const CellList<D> cells(x, radius);
  const NeighbourList list = buildNeighbourList(cells);
  EXPECT_TRUE(sameLists(list, bruteNeighbourList<D>(x, radius))) << D << "-D, R = " << radius;
  EXPECT_GE(list.meanCount(), minimumMean) << "R = " << radius;  // the test searched something
}

// Number of integer vectors k in Z^3 with |k| < r, each weighted by how many ordered pairs of
// an n^3 lattice it joins: the exact total of all row lengths for radius r*dx.
Real latticePairCount(Index n, Real r) {
  Real total = 0;
  const Index m = static_cast<Index>(r) + 1;
  for (Index x = -m; x <= m; ++x)
    for (Index y = -m; y <= m; ++y)
      for (Index z = -m; z <= m; ++z)
        if (static_cast<Real>(x * x + y * y + z * z) < r * r) {
          total += static_cast<Real>((n - std::abs(x)) * (n - std::abs(y)) * (n - std::abs(z)));
        }
  return total;
}

}  // namespace

TEST(NeighbourList, MatchesBruteForce1D) {
  const Coordinates<1> x = randomCloud<1>(1500, 0, 1, 101);
  for (const Real r : {0.0005, 0.004, 0.03, 0.3}) expectMatchesBruteForce<1>(x, r, 1.2);
}

TEST(NeighbourList, MatchesBruteForce2D) {
  const Coordinates<2> x = randomCloud<2>(1500, 0, 1, 102);
  for (const Real r : {0.01, 0.05, 0.2}) expectMatchesBruteForce<2>(x, r, 1.3);
  expectMatchesBruteForce<2>(randomCloud<2>(200, 0, 1, 103), 5.0, 200);  // R beyond the box: all pairs
}

TEST(NeighbourList, MatchesBruteForce3D) {
  const Coordinates<3> x = randomCloud<3>(2000, 0, 1, 104);
  for (const Real r : {0.03, 0.1, 0.25}) expectMatchesBruteForce<3>(x, r, 1.2);
}

TEST(NeighbourList, RebuildAfterParticlesLeaveTheBox) {
  Coordinates<3> x = randomCloud<3>(2000, 0, 1, 105);
  CellList<3> cells(x, 0.12);
  NeighbourList list = buildNeighbourList(cells);
  ASSERT_TRUE(sameLists(list, bruteNeighbourList<3>(x, 0.12)));
  const Vec3 originBefore = cells.origin();

  // Move everything: a drift out of the unit box, random jitter, and a few particles far away.
  std::mt19937_64 engine(106);
  std::uniform_real_distribution<Real> jitter(-0.05, 0.05);
  for (int step = 0; step < 3; ++step) {
    for (std::size_t a = 0; a < 3; ++a)
      for (Real& xi : x[a]) xi += 0.4 * static_cast<Real>(a + 1) + jitter(engine);
    x[0][static_cast<std::size_t>(17 + step)] = -40;  // escaped particle
    x[1][5] = x[1][6] = 80;                          // two far away, together with others' x, z
    cells.rebuild(x);
    buildNeighbourList(cells, list);  // storage reused
    EXPECT_TRUE(sameLists(list, bruteNeighbourList<3>(x, 0.12))) << "step " << step;
  }
  EXPECT_NE(cells.origin(), originBefore);  // the grid followed the particles
}

TEST(NeighbourList, RebuildInOneAndTwoDimensions) {
  Coordinates<1> x1 = randomCloud<1>(1000, 0, 1, 107);
  CellList<1> cells1(x1, 0.01);
  for (Real& v : x1[0]) v = 3 * v * v - 1;  // compress and stretch, partly outside [0, 1]
  cells1.rebuild(x1);
  EXPECT_TRUE(sameLists(buildNeighbourList(cells1), bruteNeighbourList<1>(x1, 0.01)));

  Coordinates<2> x2 = randomCloud<2>(1000, 0, 1, 108);
  CellList<2> cells2(x2, 0.05);
  for (std::size_t i = 0; i < 1000; ++i) {  // rotate by 90 degrees about the origin and shift
    const Real u = x2[0][i];
    x2[0][i] = -x2[1][i] - 2;
    x2[1][i] = u + 5;
  }
  cells2.rebuild(x2);
  EXPECT_TRUE(sameLists(buildNeighbourList(cells2), bruteNeighbourList<2>(x2, 0.05)));
}

TEST(NeighbourList, DuplicatePositions) {
  Coordinates<3> x = randomCloud<3>(600, 0, 1, 109);
  for (std::size_t a = 0; a < 3; ++a) {
    for (std::size_t i = 0; i < 300; ++i) x[a][i + 300] = x[a][i];  // second half copies the first
    x[a][1] = x[a][2] = x[a][0];                                    // a triple
  }
  const NeighbourList list = buildNeighbourList(CellList<3>(x, 0.08));
  EXPECT_TRUE(sameLists(list, bruteNeighbourList<3>(x, 0.08)));
  for (Index i = 3; i < 300; ++i) {  // a particle and its copy have identical rows
    ASSERT_TRUE(std::equal(list.row(i).begin(), list.row(i).end(), list.row(i + 300).begin(),
                           list.row(i + 300).end()));
  }
  const std::vector<Index> row0(list.row(0).begin(), list.row(0).end());
  EXPECT_TRUE(std::find(row0.begin(), row0.end(), 2) != row0.end());
  EXPECT_TRUE(std::find(row0.begin(), row0.end(), 300) != row0.end());
}

TEST(NeighbourList, LatticeNeighboursExactlyAtTheRadiusAreExcluded) {
  // dx = 0.25 and R = 0.5 are exact in binary, so the axis neighbours at 2dx sit exactly at R.
  const ParticleSet<3> block = makeBlock(Vec3(0, 0, 0), Vec3(2, 2, 2), 0.25);  // 9^3
  const Index centre = 4 + 9 * (4 + 9 * 4);
  ASSERT_EQ(block.position(centre), Vec3(1, 1, 1));

  const NeighbourList strict = buildNeighbourList(CellList<3>(block, 0.5));
  EXPECT_TRUE(sameLists(strict, bruteNeighbourList<3>(block.coordinates(), 0.5)));
  EXPECT_EQ(strict.count(centre), 27);  // the 3x3x3 cube; the 6 points at distance 2dx are out

  const Real justAbove = 0.5 * (1 + 1e-12);
  const NeighbourList inclusive = buildNeighbourList(CellList<3>(block, justAbove));
  EXPECT_TRUE(sameLists(inclusive, bruteNeighbourList<3>(block.coordinates(), justAbove)));
  EXPECT_EQ(inclusive.count(centre), 33);
}

TEST(NeighbourList, MeanCountOnALatticeIsExact) {
  // R = 2dx on a 12^3 lattice: interior rows hold the 27 lattice points with |k| < 2
  // (|k|^2 in {0, 1, 2, 3}: 1 + 6 + 12 + 8); the mean is lower because of the surface.
  const Index n = 12;
  const ParticleSet<3> block = makeBlock(Vec3(0, 0, 0), Vec3(1, 1, 1) * (n - 1) * 0.125, 0.125);
  ASSERT_EQ(block.size(), n * n * n);
  const NeighbourList list = buildNeighbourList(CellList<3>(block, 0.25));
  EXPECT_EQ(latticePairCount(n, 2), 34.0 * 34 * 34);  // offsets in {-1,0,1}^3: (3n - 2)^3
  EXPECT_EQ(static_cast<Real>(list.totalCount()), latticePairCount(n, 2));
  EXPECT_DOUBLE_EQ(list.meanCount(), latticePairCount(n, 2) / static_cast<Real>(n * n * n));
  EXPECT_NEAR(list.meanCount(), 22.74537037037037, 1e-12);  // 34^3 / 12^3
  Index interiorRows = 0;
  for (Index i = 0; i < block.size(); ++i) {
    if (block.facetCount(i) == 0) {  // one spacing from every face: the full 3x3x3 cube fits
      ASSERT_EQ(list.count(i), 27) << i;
      ++interiorRows;
    }
  }
  EXPECT_EQ(interiorRows, 10 * 10 * 10);
}

TEST(NeighbourList, RowsForPhysicalParticlesOnlyStillSeeGhosts) {
  ParticleSet<2> set = makeRectangle(Vec2(0, 0), Vec2(1, 1), 0.125);
  addGhostLayers<2>(set, Vec2(0, 0), Vec2(1, 1), 0.125, 2, allFaces(2));
  const CellList<2> cells(set, 0.26);
  const NeighbourList all = buildNeighbourList(cells);
  const NeighbourList physical = buildNeighbourList(cells, set.physicalCount());
  ASSERT_EQ(physical.rowCount(), 81);
  for (Index i = 0; i < 81; ++i) {
    ASSERT_TRUE(std::equal(physical.row(i).begin(), physical.row(i).end(), all.row(i).begin(), all.row(i).end()));
    ASSERT_EQ(physical.count(i), 13) << i;  // |k| <= 2 in 2-D, complete everywhere thanks to ghosts
  }
  EXPECT_EQ(*(physical.row(0).begin()), 0);  // sorted: the corner's own index comes first...
  EXPECT_GE(*(physical.row(0).end() - 1), set.physicalCount());  // ...its ghosts last
  EXPECT_EQ(mfwave::testing::inputErrorKey([&] { buildNeighbourList(cells, set.size() + 1); }), "rows");
}

TEST(NeighbourList, IndependentOfTheThreadCount) {
  // Large enough for the parallel paths of both the cell sort and the list build.
  const Coordinates<3> x = randomCloud<3>(60000, -1, 1, 110);
  const Real radius = 0.11;  // ~ 42 neighbours
  const int threadsBefore = omp_get_max_threads();

  omp_set_num_threads(1);
  const CellList<3> serialCells(x, radius);
  const NeighbourList serial = buildNeighbourList(serialCells);
  omp_set_num_threads(2);
  const CellList<3> parallelCells(x, radius);
  const NeighbourList parallel = buildNeighbourList(parallelCells);
  omp_set_num_threads(threadsBefore);

  EXPECT_EQ(parallelCells.cellStart(), serialCells.cellStart());
  EXPECT_EQ(parallelCells.sortedIndex(), serialCells.sortedIndex());
  EXPECT_EQ(parallel.offsets, serial.offsets);
  EXPECT_EQ(parallel.indices, serial.indices);
  EXPECT_GT(serial.meanCount(), 30);
  EXPECT_LT(serial.meanCount(), 60);
  for (Index i = 0; i < 60000; i += 2999) {  // spot check against brute force
    const std::vector<Index> row(serial.row(i).begin(), serial.row(i).end());
    ASSERT_EQ(row, bruteNeighbours<3>(x, pointOf<3>(x, i), radius)) << i;
  }
}

TEST(NeighbourList, EmptyCellList) {
  const NeighbourList list = buildNeighbourList(CellList<3>(Coordinates<3>{}, 1.0));
  EXPECT_EQ(list.rowCount(), 0);
  EXPECT_EQ(list.totalCount(), 0);
  EXPECT_EQ(list.meanCount(), 0);
}
