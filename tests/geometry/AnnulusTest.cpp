// Annulus: distances, normals and surface names on both sides, refusals, and its fill's area
// (pi (R^2 - r^2) to 1e-3, the rings' shape).

#include "core/Error.hpp"
#include "geometry/Annulus.hpp"
#include "geometry/ParticleFill.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace mfwave {
namespace {

TEST(Annulus, DistancesNormalsAndNames) {
  const Annulus<2> ring(Vec2(1, 0), 0.3, 0.4, "left");
  EXPECT_NEAR(ring.signedDistance(Vec2(1.35, 0)), -0.05, 1e-15);
  EXPECT_NEAR(ring.signedDistance(Vec2(1.5, 0)), 0.1, 1e-15);
  EXPECT_NEAR(ring.signedDistance(Vec2(1, 0.1)), 0.2, 1e-15);  // in the hole
  EXPECT_EQ(ring.surfaceName(Vec2(1.39, 0)), "left.outer");
  EXPECT_EQ(ring.surfaceName(Vec2(1.31, 0)), "left.inner");
  EXPECT_NEAR((ring.normal(Vec2(1.39, 0)) - Vec2(1, 0)).norm(), 0, 1e-15);
  EXPECT_NEAR((ring.normal(Vec2(1.31, 0)) - Vec2(-1, 0)).norm(), 0, 1e-15);
  EXPECT_THROW(Annulus<2>(Vec2(0, 0), 0.4, 0.3, "bad"), InputError);
  EXPECT_THROW(Annulus<3>(Vec3(0, 0, 0), 0.0, 0.3), InputError);
}

TEST(Annulus, FillArea) {
  const Annulus<2> ring(Vec2(0, 0), 0.03, 0.04, "ring");
  const SolidParticles<2> p = fill<2>(ring, 0.001, Vec2(0, 0));
  Real area = 0;
  for (const Real v : p.volume) area += v;
  EXPECT_NEAR(area / (3.14159265358979323846 * (0.04 * 0.04 - 0.03 * 0.03)), 1.0, 1e-3);
}

}  // namespace
}  // namespace mfwave
