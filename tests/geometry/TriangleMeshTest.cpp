// Triangle mesh solid: inside and outside of a cube and an icosphere (also at points whose rays
// would run through edges and vertices), exact distances, normals, volume and area, an
// inward-oriented mesh turned outward, the winding number, and the refusals.

#include "core/Error.hpp"
#include "geometry/MeshShapes.hpp"
#include "geometry/TriangleMesh.hpp"
#include "support/InputErrorKey.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

using namespace mfwave;

namespace {

TriangleMesh meshOf(const mfwave::testing::MeshShape& s, const std::string& name = "") {
  return TriangleMesh(s.vertices, s.triangles, name);
}

}  // namespace

TEST(TriangleMesh, CubeDistancesNormalsAndMeasures) {
  const TriangleMesh cube = meshOf(mfwave::testing::boxMesh(Vec3(0, 0, 0), Vec3(1, 1, 1)), "die");
  EXPECT_NEAR(cube.volume(), 1.0, 1e-15);
  EXPECT_NEAR(cube.area(), 6.0, 1e-14);
  EXPECT_NEAR(cube.signedDistance(Vec3(0.5, 0.5, 0.5)), -0.5, 1e-15);
  EXPECT_NEAR(cube.signedDistance(Vec3(0.5, 0.5, 0.9)), -0.1, 1e-15);
  EXPECT_NEAR(cube.signedDistance(Vec3(0.5, 0.5, 1.25)), 0.25, 1e-15);
  EXPECT_NEAR(cube.signedDistance(Vec3(1.3, 1.4, 0.5)), 0.5, 1e-15);
  EXPECT_EQ(cube.signedDistance(Vec3(1, 0.3, 0.3)), 0.0);
  EXPECT_NEAR((cube.normal(Vec3(0.5, 0.5, 0.9)) - Vec3(0, 0, 1)).norm(), 0, 1e-15);
  EXPECT_NEAR((cube.normal(Vec3(0.05, 0.4, 0.5)) - Vec3(-1, 0, 0)).norm(), 0, 1e-15);
  EXPECT_EQ(cube.surfaceName(Vec3(0, 0, 0)), "die.surface");
  EXPECT_EQ(cube.bounds().upper, Vec3(1, 1, 1));
}

TEST(TriangleMesh, InsideAtPointsLevelWithEdgesAndVertices) {
  // Points on the diagonals and mid-planes of the cube, where an axis-aligned ray would run through
  // the faces' shared diagonals or along their edges.
  const TriangleMesh cube = meshOf(mfwave::testing::boxMesh(Vec3(0, 0, 0), Vec3(1, 1, 1)));
  for (const Vec3& p : {Vec3(0.5, 0.5, 0.5), Vec3(0.25, 0.25, 0.25), Vec3(0.75, 0.25, 0.5), Vec3(0.5, 0.5, 0.999999)})
    EXPECT_LT(cube.signedDistance(p), 0) << p.transpose();
  for (const Vec3& p : {Vec3(1.5, 0.5, 0.5), Vec3(-0.5, -0.5, -0.5), Vec3(0.5, 0.5, 1.000001), Vec3(2, 2, 2)})
    EXPECT_GT(cube.signedDistance(p), 0) << p.transpose();
}

TEST(TriangleMesh, IcosphereAgreesWithTheWindingNumber) {
  const mfwave::testing::MeshShape shape = mfwave::testing::icosphereMesh(Vec3(0, 0, 0), 1.0, 3);
  const TriangleMesh sphere = meshOf(shape);
  EXPECT_NEAR(sphere.volume(), mfwave::testing::meshShapeVolume(shape), 1e-12);
  EXPECT_GT(mfwave::testing::meshShapeVolume(shape), 0);  // the helper's triangles point out
  std::mt19937 random(11);
  std::uniform_real_distribution<Real> coordinate(-1.2, 1.2);
  for (int k = 0; k < 200; ++k) {
    const Vec3 p(coordinate(random), coordinate(random), coordinate(random));
    const Real w = sphere.windingNumber(p);
    EXPECT_NEAR(w, w > 0.5 ? 1.0 : 0.0, 1e-10);
    EXPECT_EQ(sphere.signedDistance(p) < 0, w > 0.5) << p.transpose();
  }
  // Through vertices: the icosahedron's vertices lie on the rays from the centre along (0, 1, g).
  const Vec3 vertex = shape.vertices[1];
  EXPECT_LT(sphere.signedDistance(0.99 * vertex), 0);
  EXPECT_GT(sphere.signedDistance(1.01 * vertex), 0);
  EXPECT_NEAR((sphere.normal(1.2 * vertex) - vertex).norm(), 0, 0.1);
}

TEST(TriangleMesh, AnInwardOrientedMeshIsTurnedOutward) {
  mfwave::testing::MeshShape inward = mfwave::testing::boxMesh(Vec3(0, 0, 0), Vec3(2, 2, 2));
  for (auto& t : inward.triangles) std::swap(t[0], t[1]);
  const TriangleMesh cube = meshOf(inward);
  EXPECT_NEAR(cube.volume(), 8.0, 1e-14);
  EXPECT_NEAR((cube.normal(Vec3(1, 1, 1.9)) - Vec3(0, 0, 1)).norm(), 0, 1e-15);
  EXPECT_LT(cube.signedDistance(Vec3(1, 1, 1)), 0);
}

TEST(TriangleMesh, RefusesOpenAndInconsistentMeshes) {
  mfwave::testing::MeshShape open = mfwave::testing::boxMesh(Vec3(0, 0, 0), Vec3(1, 1, 1));
  open.triangles.pop_back();
  try {
    meshOf(open, "part");
    ADD_FAILURE() << "an open mesh was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "part.triangles");
    EXPECT_NE(e.problem().find("3 boundary edges"), std::string::npos) << e.problem();
  }
  mfwave::testing::MeshShape twisted = mfwave::testing::boxMesh(Vec3(0, 0, 0), Vec3(1, 1, 1));
  std::swap(twisted.triangles[4][1], twisted.triangles[4][2]);
  EXPECT_EQ(mfwave::testing::inputErrorKey([&] { meshOf(twisted); }), "mesh.triangles");
  mfwave::testing::MeshShape flat = mfwave::testing::boxMesh(Vec3(0, 0, 0), Vec3(1, 1, 1));
  flat.vertices[7] = flat.vertices[6];  // a triangle of the top face collapses
  EXPECT_EQ(mfwave::testing::inputErrorKey([&] { meshOf(flat); }), "mesh.triangles");
}
