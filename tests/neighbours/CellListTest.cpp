// CellList: grid invariants, the counting sort, point queries against brute force, and the
// awkward clouds (far-flung, flat, empty, non-finite).

#include "support/InputErrorKey.hpp"
#include "BruteForce.hpp"

#include "core/Error.hpp"
#include "neighbours/CellList.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <numeric>
#include <string>

using namespace mfwave;
using namespace mfwave::testing;

namespace {

// Sorted neighbours of y reported by the cell list, checking the reported squared distances.
template <int D>
std::vector<Index> queried(const CellList<D>& cells, const Coordinates<D>& x, const Vec<D>& y, Real radius) {
  std::vector<Index> found;
  cells.forEachNeighbour(y, radius, [&](Index j, Real d2) {
    EXPECT_DOUBLE_EQ(d2, distanceSquared<D>(x, j, y));
    found.push_back(j);
  });
  std::sort(found.begin(), found.end());
  return found;
}

template <int D>
void expectQueriesMatchBruteForce(const Coordinates<D>& x, Real radius, unsigned seed) {
  const CellList<D> cells(x, radius);
  const Coordinates<D> queries = randomCloud<D>(200, -0.5, 1.5, seed);  // also outside the cloud
  Index total = 0;
  for (Index q = 0; q < 200; ++q) {
    const Vec<D> y = pointOf<D>(queries, q);
    for (const Real r : {radius, radius / 2}) {
      const std::vector<Index> expected = bruteNeighbours<D>(x, y, r);
      ASSERT_EQ(queried<D>(cells, x, y, r), expected) << "query " << q << " radius " << r;
      total += static_cast<Index>(expected.size());
    }
  }
  EXPECT_GT(total, 200);  // the queries did find particles
  EXPECT_TRUE(queried<D>(cells, x, Vec<D>::Constant(1e6), radius).empty());
}

}  // namespace

TEST(CellList, RadiusMustBePositiveAndFinite) {
  EXPECT_EQ(mfwave::testing::inputErrorKey([] { CellList<3> c(0.0); }), "radius");
  EXPECT_EQ(mfwave::testing::inputErrorKey([] { CellList<2> c(-1.0); }), "radius");
  EXPECT_EQ(mfwave::testing::inputErrorKey([] { CellList<1> c(std::numeric_limits<Real>::quiet_NaN()); }), "radius");
  EXPECT_EQ(mfwave::testing::inputErrorKey([] { CellList<1> c(std::numeric_limits<Real>::infinity()); }), "radius");
  EXPECT_EQ(mfwave::testing::inputErrorKey([] { CellList<1> c(0.5); }), "");
}

TEST(CellList, SortedStorageIsAStableCountingSort) {
  const Coordinates<3> x = randomCloud<3>(3000, 0, 1, 7);
  const CellList<3> cells(x, 0.1);
  ASSERT_EQ(cells.size(), 3000);
  EXPECT_EQ(cells.cellCount(), cells.cellsAlong(0) * cells.cellsAlong(1) * cells.cellsAlong(2));
  EXPECT_GE(cells.cellsAlong(0), 8);  // ~1 / 0.1 cells per axis, not one big cell
  for (int a = 0; a < 3; ++a) EXPECT_GE(cells.cellSize(a), 0.1);

  const auto& start = cells.cellStart();
  ASSERT_EQ(static_cast<Index>(start.size()), cells.cellCount() + 1);
  EXPECT_EQ(start.front(), 0);
  EXPECT_EQ(start.back(), 3000);
  std::vector<Index> seen(cells.sortedIndex());
  std::sort(seen.begin(), seen.end());
  std::vector<Index> all(3000);
  std::iota(all.begin(), all.end(), 0);
  EXPECT_EQ(seen, all);  // a permutation

  for (Index c = 0; c < cells.cellCount(); ++c) {
    const auto b = static_cast<std::size_t>(start[static_cast<std::size_t>(c)]);
    const auto e = static_cast<std::size_t>(start[static_cast<std::size_t>(c) + 1]);
    ASSERT_LE(b, e);
    ASSERT_TRUE(std::is_sorted(cells.sortedIndex().begin() + static_cast<long>(b),
                               cells.sortedIndex().begin() + static_cast<long>(e)));
    for (std::size_t s = b; s < e; ++s) {
      const Index i = cells.sortedIndex()[s];
      const Vec3 p = pointOf<3>(x, i);
      for (int a = 0; a < 3; ++a) ASSERT_EQ(cells.sortedCoordinate(a)[s], p[a]);
      const auto cell = cells.cellOfPoint(p);
      const Index linear = std::min(cell[0], cells.cellsAlong(0) - 1) +
                           cells.cellsAlong(0) * (std::min(cell[1], cells.cellsAlong(1) - 1) +
                                                  cells.cellsAlong(1) * std::min(cell[2], cells.cellsAlong(2) - 1));
      ASSERT_EQ(linear, c) << "particle " << i;
    }
  }
}

TEST(CellList, PointQueriesMatchBruteForce1D) {
  expectQueriesMatchBruteForce<1>(randomCloud<1>(500, 0, 1, 11), 0.01, 12);
}
TEST(CellList, PointQueriesMatchBruteForce2D) {
  expectQueriesMatchBruteForce<2>(randomCloud<2>(1500, 0, 1, 13), 0.06, 14);
}
TEST(CellList, PointQueriesMatchBruteForce3D) {
  expectQueriesMatchBruteForce<3>(randomCloud<3>(3000, 0, 1, 15), 0.15, 16);
}

TEST(CellList, QueryRadiusLargerThanTheSearchRadiusIsRejected) {
  const CellList<2> cells(randomCloud<2>(10, 0, 1, 1), 0.1);
  EXPECT_EQ(mfwave::testing::inputErrorKey([&] { cells.forEachNeighbour(Vec2(0.5, 0.5), 0.2, [](Index, Real) {}); }), "radius");
}

TEST(CellList, FarFlungParticleKeepsTheGridSmall) {
  Coordinates<3> x = randomCloud<3>(500, 0, 1, 21);
  x[0][3] = 1e9;  // one particle escaped: the box is 1e9 wide, cells of 0.05 would be 2e10 per axis
  x[2][4] = -1e9;
  const CellList<3> cells(x, 0.05);
  EXPECT_LE(cells.cellCount(), 500);
  for (int a = 0; a < 3; ++a) EXPECT_GE(cells.cellSize(a), 0.05);
  EXPECT_EQ(queried<3>(cells, x, pointOf<3>(x, 3), 0.05), std::vector<Index>{3});
  EXPECT_EQ(queried<3>(cells, x, pointOf<3>(x, 10), 0.05), bruteNeighbours<3>(x, pointOf<3>(x, 10), 0.05));
}

TEST(CellList, FlatCloudInThreeDimensions) {
  Coordinates<3> x = randomCloud<3>(800, 0, 1, 23);
  std::fill(x[2].begin(), x[2].end(), 0.25);  // all on one plane: zero extent along z
  const CellList<3> cells(x, 0.1);
  EXPECT_EQ(cells.cellsAlong(2), 1);
  for (Index i = 0; i < 800; i += 37) {
    EXPECT_EQ(queried<3>(cells, x, pointOf<3>(x, i), 0.1), bruteNeighbours<3>(x, pointOf<3>(x, i), 0.1));
  }
}

TEST(CellList, EmptyAndSingleParticle) {
  CellList<2> cells(Coordinates<2>{}, 1.0);
  EXPECT_EQ(cells.size(), 0);
  Index calls = 0;
  cells.forEachNeighbour(Vec2(0, 0), 1.0, [&](Index, Real) { ++calls; });
  EXPECT_EQ(calls, 0);

  const Coordinates<2> one{std::vector<Real>{3}, std::vector<Real>{4}};
  cells.rebuild(one);
  EXPECT_EQ(cells.size(), 1);
  EXPECT_EQ(queried<2>(cells, one, Vec2(3.5, 4), 1.0), std::vector<Index>{0});
  EXPECT_TRUE(queried<2>(cells, one, Vec2(4, 4), 1.0).empty());  // exactly at R: excluded
}

TEST(CellList, BadPositionsAreRejected) {
  Coordinates<2> x = randomCloud<2>(20, 0, 1, 3);
  x[1][7] = std::numeric_limits<Real>::quiet_NaN();
  EXPECT_THROW(CellList<2>(x, 0.1), Error);
  x[1][7] = std::numeric_limits<Real>::infinity();
  EXPECT_THROW(CellList<2>(x, 0.1), Error);
  x[1].pop_back();
  EXPECT_EQ(mfwave::testing::inputErrorKey([&] { CellList<2> c(x, 0.1); }), "positions");
}

TEST(CellList, BuildsFromAParticleSet) {
  ParticleSet<2> set;
  set.add(Vec2(0, 0), 1);
  set.add(Vec2(0.5, 0), 1);
  set.add(Vec2(2, 0), 1, ParticleKind::Ghost);
  const CellList<2> cells(set, 1.0);
  EXPECT_EQ(cells.size(), 3);
  EXPECT_EQ(queried<2>(cells, set.coordinates(), Vec2(0.4, 0), 1.0), (std::vector<Index>{0, 1}));
  EXPECT_EQ(queried<2>(cells, set.coordinates(), Vec2(1.4, 0), 1.0), (std::vector<Index>{1, 2}));
}
