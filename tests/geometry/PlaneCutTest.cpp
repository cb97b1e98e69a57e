// Plane cuts of the unit cube: closed-form volumes and areas against hand values (axis-aligned
// slabs, the diagonal of a square, the cube's central hexagon) and a sampled count for an
// arbitrary plane; complementary sides add to one; a plane on a face counts once.

#include "geometry/PlaneCut.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace mfwave;

namespace {

// Fraction of the unit cube with n . y <= s, by the midpoint rule on a fine grid.
Real sampledCutVolume(const Vec3& n, Real s) {
  const int m = 120;
  long count = 0;
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j)
      for (int k = 0; k < m; ++k) {
        const Vec3 y((i + 0.5) / m - 0.5, (j + 0.5) / m - 0.5, (k + 0.5) / m - 0.5);
        if (n.dot(y) <= s) ++count;
      }
  return static_cast<Real>(count) / (static_cast<Real>(m) * m * m);
}

}  // namespace

TEST(PlaneCut, AxisAlignedSlabs) {
  const PlaneCut quarter = planeCutOfUnitCube<2>(Vec2(1, 0), -0.25);
  EXPECT_DOUBLE_EQ(quarter.volume, 0.25);
  EXPECT_DOUBLE_EQ(quarter.area, 1.0);
  const PlaneCut high = planeCutOfUnitCube<3>(Vec3(0, 0, -1), -0.1);  // z >= 0.1
  EXPECT_NEAR(high.volume, 0.4, 1e-15);
  EXPECT_DOUBLE_EQ(high.area, 1.0);
  EXPECT_EQ(planeCutOfUnitCube<3>(Vec3(0, 1, 0), -0.7).volume, 0.0);
  EXPECT_EQ(planeCutOfUnitCube<3>(Vec3(0, 1, 0), 0.7).volume, 1.0);
}

TEST(PlaneCut, AFaceOnTheCubeCountsOnTheSolidsSide) {
  // The plane x = 1/2: the whole cube is inside and holds the face; from the other side, nothing.
  const PlaneCut inside = planeCutOfUnitCube<3>(Vec3(1, 0, 0), 0.5);
  EXPECT_EQ(inside.volume, 1.0);
  EXPECT_EQ(inside.area, 1.0);
  const PlaneCut outside = planeCutOfUnitCube<3>(Vec3(1, 0, 0), -0.5);
  EXPECT_EQ(outside.volume, 0.0);
  EXPECT_EQ(outside.area, 0.0);
}

TEST(PlaneCut, DiagonalsOfTheSquareAndTheCube) {
  const Vec2 d2 = Vec2(1, 1).normalized();
  EXPECT_NEAR(planeCutOfUnitCube<2>(d2, 0).volume, 0.5, 1e-15);
  EXPECT_NEAR(planeCutOfUnitCube<2>(d2, 0).area, std::sqrt(2.0), 1e-14);
  // The corner triangle below x + y = -1/2 (legs 1/2): area 1/8, hypotenuse sqrt(2) / 2.
  EXPECT_NEAR(planeCutOfUnitCube<2>(d2, -0.5 / std::sqrt(2.0)).volume, 0.125, 1e-15);
  EXPECT_NEAR(planeCutOfUnitCube<2>(d2, -0.5 / std::sqrt(2.0)).area, std::sqrt(2.0) / 2, 1e-14);
  // The plane through the centre normal to (1, 1, 1) cuts a regular hexagon of side sqrt(2) / 2.
  const Vec3 d3 = Vec3(1, 1, 1).normalized();
  EXPECT_NEAR(planeCutOfUnitCube<3>(d3, 0).volume, 0.5, 1e-15);
  EXPECT_NEAR(planeCutOfUnitCube<3>(d3, 0).area, 3 * std::sqrt(3.0) / 4, 1e-14);
}

TEST(PlaneCut, ArbitraryPlanesMatchSampling) {
  const Vec3 n = Vec3(0.3, -0.8, 0.52).normalized();
  for (const Real s : {-0.6, -0.35, -0.1, 0.0, 0.2, 0.45}) {
    const PlaneCut cut = planeCutOfUnitCube<3>(n, s);
    EXPECT_NEAR(cut.volume, sampledCutVolume(n, s), 2e-4) << "s = " << s;
    EXPECT_NEAR(cut.volume + planeCutOfUnitCube<3>(Vec3(-n), -s).volume, 1.0, 1e-14);
    // The area is the volume's rate of change with the plane's offset.
    const Real h = 1e-6;
    const Real slope = (planeCutOfUnitCube<3>(n, s + h).volume - planeCutOfUnitCube<3>(n, s - h).volume) / (2 * h);
    EXPECT_NEAR(cut.area, slope, 1e-6) << "s = " << s;
  }
  // A nearly axis-aligned plane (a component below the dropped threshold) stays continuous.
  const Vec3 almost = Vec3(1, 1e-8, 0).normalized();
  EXPECT_NEAR(planeCutOfUnitCube<3>(almost, 0.1).volume, 0.6, 1e-7);
}
