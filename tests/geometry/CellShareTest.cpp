// One cell's share of a solid: whole, empty, cut by a flat face (exact), and a quarter of a
// disc's cell by subdivision.

#include "geometry/Ball.hpp"
#include "geometry/BoxSolid.hpp"
#include "geometry/CellShare.hpp"
#include "geometry/HalfSpace.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace mfwave;

TEST(CellShare, WholeEmptyAndFlatCuts) {
  const BoxSolid<2> box(Vec2(0, 0), Vec2(1, 1));
  const CellShare<2> whole = cellShare<2>(box, Vec2(0.5, 0.5), 0.2, 3);
  EXPECT_NEAR(whole.volume, 0.04, 1e-16);
  EXPECT_EQ(whole.area, 0.0);
  EXPECT_EQ(cellShare<2>(box, Vec2(1.5, 0.5), 0.2, 3).volume, 0.0);
  // The corner cell centred on (1, 1): a quarter inside, holding 0.1 + 0.1 of the faces.
  const CellShare<2> corner = cellShare<2>(box, Vec2(1, 1), 0.2, 3);
  EXPECT_NEAR(corner.volume, 0.01, 1e-16);
  EXPECT_NEAR((corner.moment / corner.volume - Vec2(0.95, 0.95)).norm(), 0, 1e-12);
  // 0.1 of each face, less the finest sub-cell at the corner, which counts one face of its two.
  EXPECT_NEAR(corner.area, 0.2 - 0.2 / 8, 1e-12);
  // A tilted flat face: exact whatever the depth.
  const HalfSpace<3> slope(Vec3(0.03, 0, 0), Vec3(1, 0.4, -0.3));
  const Vec3 n = Vec3(1, 0.4, -0.3).normalized();
  for (const int depth : {0, 2}) {
    const CellShare<3> cut = cellShare<3>(slope, Vec3(0, 0, 0), 0.1, depth);
    // The half-space cuts through the middle of the cell: half a cell plus the slab 0.03 * n_x.
    EXPECT_GT(cut.volume, 0.5e-3);
    EXPECT_LT(cut.volume, 1e-3);
    const CellShare<3> other = cellShare<3>(HalfSpace<3>(Vec3(0.03, 0, 0), Vec3(-n)), Vec3(0, 0, 0), 0.1, depth);
    EXPECT_NEAR(cut.volume + other.volume, 1e-3, 1e-15);
    EXPECT_NEAR(cut.area, other.area, 1e-15);
  }
  EXPECT_NEAR(cellShare<3>(slope, Vec3(0, 0, 0), 0.1, 0).volume, cellShare<3>(slope, Vec3(0, 0, 0), 0.1, 3).volume, 1e-15);
}

TEST(CellShare, ADiscsQuarterByTheCellAtItsCentre) {
  // A cell much larger than a small disc centred on its corner holds a quarter of it.
  const Ball<2> disc(Vec2(0, 0), 0.3);
  const CellShare<2> share = cellShare<2>(disc, Vec2(0.5, 0.5), 1.0, 6);
  EXPECT_NEAR(share.volume, kPi * 0.09 / 4, 1e-4);
  // Tangent-plane pieces: second order in curvature x finest side (1/0.3 x 1/64 here).
  EXPECT_NEAR(share.area, 2 * kPi * 0.3 / 4, 0.01 * 2 * kPi * 0.3 / 4);
}
