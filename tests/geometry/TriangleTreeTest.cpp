// Triangle tree: its nearest triangle agrees in distance with a sweep over every triangle, for
// points inside, outside and far away; a ray visits every triangle it crosses.

#include "geometry/MeshShapes.hpp"
#include "geometry/TriangleTree.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <set>

using namespace mfwave;

namespace {

// Distance from p to triangle t by dense sampling of its barycentric coordinates plus its sides:
// independent of the tree's closed form, accurate to about the sampling step.
Real sampledTriangleDistance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  Real best = std::numeric_limits<Real>::infinity();
  const int n = 60;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; i + j <= n; ++j) {
      const Real u = Real(i) / n, v = Real(j) / n;
      best = std::min(best, (a + u * (b - a) + v * (c - a) - p).norm());
    }
  return best;
}

}  // namespace

TEST(TriangleTree, NearestMatchesASweepOverAllTriangles) {
  const mfwave::testing::MeshShape sphere = mfwave::testing::icosphereMesh(Vec3(0.1, -0.2, 0.3), 1.0, 2);
  const TriangleTree tree(sphere.vertices, sphere.triangles);
  std::mt19937 random(7);
  std::uniform_real_distribution<Real> coordinate(-2.0, 2.0);
  for (int k = 0; k < 40; ++k) {
    const Vec3 p(coordinate(random), coordinate(random), coordinate(random));
    const TriangleTree::Nearest found = tree.nearest(p);
    Real sweep = std::numeric_limits<Real>::infinity();
    for (const auto& t : sphere.triangles)
      sweep = std::min(sweep, sampledTriangleDistance(p, sphere.vertices[static_cast<std::size_t>(t[0])],
                                                      sphere.vertices[static_cast<std::size_t>(t[1])],
                                                      sphere.vertices[static_cast<std::size_t>(t[2])]));
    // Sampling overestimates by at most a sampling step (edge ~0.3 / 60).
    EXPECT_LE(std::sqrt(found.squaredDistance), sweep + 1e-12);
    EXPECT_GE(std::sqrt(found.squaredDistance), sweep - 0.01);
    const auto& t = sphere.triangles[static_cast<std::size_t>(found.triangle)];
    EXPECT_NEAR(sampledTriangleDistance(p, sphere.vertices[static_cast<std::size_t>(t[0])],
                                        sphere.vertices[static_cast<std::size_t>(t[1])],
                                        sphere.vertices[static_cast<std::size_t>(t[2])]),
                std::sqrt(found.squaredDistance), 0.01);
  }
}

TEST(TriangleTree, ExactDistancesToABoxMesh) {
  const mfwave::testing::MeshShape box = mfwave::testing::boxMesh(Vec3(0, 0, 0), Vec3(2, 1, 1));
  const TriangleTree tree(box.vertices, box.triangles);
  EXPECT_NEAR(std::sqrt(tree.nearest(Vec3(1, 0.5, 0.6)).squaredDistance), 0.4, 1e-15);
  EXPECT_NEAR(std::sqrt(tree.nearest(Vec3(2.3, 1.4, 0.5)).squaredDistance), 0.5, 1e-15);
  EXPECT_NEAR(std::sqrt(tree.nearest(Vec3(-1, -1, -1)).squaredDistance), std::sqrt(3.0), 1e-15);
}

TEST(TriangleTree, ARayVisitsTheTrianglesItCrosses) {
  const mfwave::testing::MeshShape box = mfwave::testing::boxMesh(Vec3(0, 0, 0), Vec3(1, 1, 1));
  const TriangleTree tree(box.vertices, box.triangles);
  std::set<Index> seen;
  tree.alongRay(Vec3(0.3, 0.4, -1), Vec3(0.01, 0.02, 1).normalized(),
                [&](Index t, const Vec3&, const Vec3&, const Vec3&) { seen.insert(t); });
  // The bottom face (triangles 8, 9) and the top face (10, 11) are crossed.
  EXPECT_TRUE(seen.count(8) + seen.count(9) >= 1);
  EXPECT_TRUE(seen.count(10) + seen.count(11) >= 1);
}
