// Particles from solids: volumes add up to the solid's (balls in 2-D and 3-D, a box with a hole,
// a polygon, an extruded polygon, meshes), the surface area of a ball, where particles sit and
// which are surface ones, sliver merging, a box whose faces run through nodes, and refusals.

#include "geometry/Ball.hpp"
#include "geometry/BoxSolid.hpp"
#include "geometry/Csg.hpp"
#include "geometry/ExtrudedPolygon.hpp"
#include "geometry/HalfSpace.hpp"
#include "geometry/MeshShapes.hpp"
#include "geometry/ParticleFill.hpp"
#include "geometry/Polygon.hpp"
#include "geometry/TriangleMesh.hpp"
#include "support/InputErrorKey.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numeric>

using namespace mfwave;

namespace {

template <int D>
Real totalVolume(const SolidParticles<D>& p) {
  return std::accumulate(p.volume.begin(), p.volume.end(), 0.0);
}
template <int D>
Real totalArea(const SolidParticles<D>& p) {
  return std::accumulate(p.area.begin(), p.area.end(), 0.0);
}

// The checks every fill must pass: every particle inside (or on) the solid, volumes between the
// sliver threshold and a few cells, surface particles with unit normals and area, the others
// with neither.
template <int D>
void expectSoundFill(const Solid<D>& solid, const SolidParticles<D>& p, Real dx) {
  const Real cell = std::pow(dx, D);
  ASSERT_GT(p.size(), 0);
  for (Index i = 0; i < p.size(); ++i) {
    const auto s = static_cast<std::size_t>(i);
    EXPECT_LE(solid.signedDistance(p.position[s]), 1e-12) << "particle " << i;
    EXPECT_GE(p.volume[s], 0.1 * cell * (1 - 1e-12));
    EXPECT_LE(p.volume[s], 2.5 * cell);
    if (p.surface[s]) {
      EXPECT_NEAR(p.normal[s].norm(), 1.0, 1e-12);
      EXPECT_GT(p.area[s], 0);
    } else {
      EXPECT_EQ(p.normal[s], Vec<D>::Zero());
      EXPECT_EQ(p.area[s], 0);
      EXPECT_NEAR(p.volume[s], cell, 1e-12 * cell);
    }
  }
}

}  // namespace

TEST(ParticleFill, DiscVolumeAndPerimeter) {
  const Vec2 centre(0.013, -0.021);
  const Ball<2> disc(centre, 1.0);
  const Real dx = 0.1;
  const SolidParticles<2> p = fill<2>(disc, dx, Vec2(0, 0));
  expectSoundFill(disc, p, dx);
  EXPECT_NEAR(totalVolume(p), kPi, 1e-3 * kPi);
  EXPECT_NEAR(totalArea(p), 2 * kPi, 1e-3 * 2 * kPi);  // measured 6e-5
  for (Index i = 0; i < p.size(); ++i) {
    const auto s = static_cast<std::size_t>(i);
    if (!p.surface[s]) {
      // Whole cells keep their node.
      EXPECT_NEAR((p.position[s] - dx * Vec2(Real(p.cell[s][0]), Real(p.cell[s][1]))).norm(), 0, 1e-15);
      continue;
    }
    EXPECT_GT(p.normal[s].dot((p.position[s] - centre).normalized()), 0.9999);
    EXPECT_GT((p.position[s] - centre).norm(), 1 - 1.5 * dx);  // surface particles lie near the surface
  }
}

TEST(ParticleFill, BallVolumeAndSurfaceArea) {
  const Vec3 centre(0.013, -0.021, 0.007);
  const Ball<3> ball(centre, 1.0);
  const Real dx = 0.1;
  const SolidParticles<3> p = fill<3>(ball, dx, Vec3(0, 0, 0));
  expectSoundFill(ball, p, dx);
  EXPECT_NEAR(totalVolume(p), 4 * kPi / 3, 1e-3 * 4 * kPi / 3);
  EXPECT_NEAR(totalArea(p), 4 * kPi, 1e-3 * 4 * kPi);  // measured 4e-6
}

TEST(ParticleFill, BoxWithABallRemoved) {
  const auto block = std::make_shared<BoxSolid<3>>(Vec3(-0.52, -0.47, -0.3), Vec3(0.51, 0.43, 0.33), "block");
  const auto hole = std::make_shared<Ball<3>>(Vec3(0.05, -0.02, 0.01), 0.25, "hole");
  const SolidPtr<3> solid = subtract<3>(block, hole);
  const Real dx = 0.05;
  const SolidParticles<3> p = fill<3>(*solid, dx, Vec3(0, 0, 0));
  expectSoundFill(*solid, p, dx);
  const Real exact = 1.03 * 0.90 * 0.63 - 4 * kPi / 3 * 0.25 * 0.25 * 0.25;
  EXPECT_NEAR(totalVolume(p), exact, 1e-3 * exact);
  // The hole's surface particles face its centre.
  for (Index i = 0; i < p.size(); ++i) {
    const auto s = static_cast<std::size_t>(i);
    if (p.surface[s] && solid->surfaceName(p.position[s]) == "hole.surface") {
      EXPECT_GT(p.normal[s].dot((Vec3(0.05, -0.02, 0.01) - p.position[s]).normalized()), 0.999);
    }
  }
}

TEST(ParticleFill, AHoleSmallerThanACellKeepsItsParticleInTheSolid) {
  // The cell of the node (0, 0) is cut by a hole around that node: the centroid of what is left is
  // the hole's centre, so the particle moves to the hole's surface.
  const auto plate = std::make_shared<BoxSolid<2>>(Vec2(-0.52, -0.53), Vec2(0.51, 0.54));
  const auto pore = std::make_shared<Ball<2>>(Vec2(0, 0), 0.03, "pore");
  const SolidPtr<2> solid = subtract<2>(plate, pore);
  const Real dx = 0.1;
  const SolidParticles<2> p = fill<2>(*solid, dx, Vec2(0, 0));
  expectSoundFill(*solid, p, dx);
  const Real exact = 1.03 * 1.07 - kPi * 0.03 * 0.03;
  EXPECT_NEAR(totalVolume(p), exact, 1e-4 * exact);
  Index found = 0;
  for (Index i = 0; i < p.size(); ++i) {
    const auto s = static_cast<std::size_t>(i);
    if (p.cell[s] != std::array<Index, 2>{0, 0}) continue;
    ++found;
    EXPECT_NEAR(p.position[s].norm(), 0.03, 1e-12);
    EXPECT_EQ(solid->surfaceName(p.position[s]), "pore.surface");
    // The pore's radius is 2.4 finest sub-cells: its perimeter is resolved to a few percent.
    EXPECT_NEAR(p.area[s], 2 * kPi * 0.03, 0.05 * 2 * kPi * 0.03);
  }
  EXPECT_EQ(found, 1);
}

TEST(ParticleFill, PolygonAndExtrudedPolygon) {
  // A non-convex pentagon with oblique edges.
  const std::vector<Vec2> vertices = {Vec2(-0.83, -0.61), Vec2(0.92, -0.47), Vec2(0.71, 0.88), Vec2(0.05, 0.12),
                                      Vec2(-0.66, 0.79)};
  const Polygon polygon(vertices);
  const Real dx = 0.05;
  const SolidParticles<2> flat = fill<2>(polygon, dx, Vec2(0.01, 0.02));
  expectSoundFill(polygon, flat, dx);
  EXPECT_NEAR(totalVolume(flat), polygon.shape().area(), 1e-3 * polygon.shape().area());

  const ExtrudedPolygon prism(vertices, -0.33, 0.41);
  const SolidParticles<3> solid = fill<3>(prism, 0.1, Vec3(0.01, 0.02, 0.03));
  expectSoundFill(prism, solid, 0.1);
  EXPECT_NEAR(totalVolume(solid), prism.volume(), 1e-3 * prism.volume());
}

TEST(ParticleFill, MeshesOfASphereAndACube) {
  const mfwave::testing::MeshShape sphereShape = mfwave::testing::icosphereMesh(Vec3(0.02, -0.01, 0.03), 1.0, 2);
  const TriangleMesh sphere(sphereShape.vertices, sphereShape.triangles);
  const SolidParticles<3> p = fill<3>(sphere, 0.2, Vec3(0, 0, 0));
  expectSoundFill(sphere, p, 0.2);
  EXPECT_NEAR(totalVolume(p), sphere.volume(), 1e-3 * sphere.volume());

  // A cube whose faces fall between lattice planes at odd fractions.
  const mfwave::testing::MeshShape cubeShape = mfwave::testing::boxMesh(Vec3(0.013, 0.027, 0.041), Vec3(1.013, 1.027, 1.041));
  const TriangleMesh cube(cubeShape.vertices, cubeShape.triangles);
  const SolidParticles<3> q = fill<3>(cube, 0.1, Vec3(0, 0, 0));
  expectSoundFill(cube, q, 0.1);
  EXPECT_NEAR(totalVolume(q), 1.0, 1e-3);
  EXPECT_NEAR(totalArea(q), 6.0, 0.05 * 6.0);  // short along the edges (CellShare.hpp)
}

TEST(ParticleFill, ABoxWithFacesThroughTheNodes) {
  // Nodes on the faces: their cells are cut in half (quarters at the corners), exactly.
  const BoxSolid<2> box(Vec2(0, 0), Vec2(1, 1));
  const Real dx = 0.1;
  const SolidParticles<2> p = fill<2>(box, dx, Vec2(0, 0));
  ASSERT_EQ(p.size(), 121);
  EXPECT_NEAR(totalVolume(p), 1.0, 1e-14);
  Index surface = 0;
  for (Index i = 0; i < p.size(); ++i) {
    const auto s = static_cast<std::size_t>(i);
    const bool edgeX = p.cell[s][0] == 0 || p.cell[s][0] == 10;
    const bool edgeY = p.cell[s][1] == 0 || p.cell[s][1] == 10;
    const Real expected = dx * dx * (edgeX ? 0.5 : 1.0) * (edgeY ? 0.5 : 1.0);
    EXPECT_NEAR(p.volume[s], expected, 1e-15);
    surface += p.surface[s];
    if (p.cell[s][0] == 0 && !edgeY) {
      EXPECT_NEAR(p.position[s].x(), 0.025, 1e-14);  // the centroid of the half cell
      EXPECT_EQ(p.normal[s], Vec2(-1, 0));
      EXPECT_NEAR(p.area[s], dx, 1e-14);
    }
  }
  EXPECT_EQ(surface, 40);
  // Shifted by half a cell the cells fit the box: whole cells, the outer ring holding the faces.
  const SolidParticles<2> fitted = fill<2>(box, dx, Vec2(0.05, 0.05));
  ASSERT_EQ(fitted.size(), 100);
  EXPECT_NEAR(totalVolume(fitted), 1.0, 1e-14);
  EXPECT_EQ(std::count(fitted.surface.begin(), fitted.surface.end(), 1), 36);
  // 4 of 4.0: the four corner sub-cells count one face of two (CellShare.hpp).
  EXPECT_NEAR(totalArea(fitted), 4.0 - 4 * dx / 8, 1e-12);
}

TEST(ParticleFill, SliversAreMergedKeepingTheVolume) {
  const Ball<2> disc(Vec2(0.0137, 0.0291), 0.73);
  const Real dx = 0.1;
  FillOptions all;
  all.sliverFraction = 0;
  const SolidParticles<2> every = fill<2>(disc, dx, Vec2(0, 0), all);
  const SolidParticles<2> merged = fill<2>(disc, dx, Vec2(0, 0));
  EXPECT_LT(merged.size(), every.size());
  EXPECT_NEAR(totalVolume(merged), totalVolume(every), 1e-14);
  EXPECT_NEAR(totalArea(merged), totalArea(every), 1e-14);
  EXPECT_LT(*std::min_element(every.volume.begin(), every.volume.end()), 0.1 * dx * dx);
  EXPECT_GE(*std::min_element(merged.volume.begin(), merged.volume.end()), 0.1 * dx * dx);
  // A strip thinner than a sliver still gives one particle holding all of it. (Its faces and
  // corners lie on sub-cell boundaries or alone in a finest sub-cell, so its volume is exact.)
  const BoxSolid<2> thin(Vec2(0.0, 0.0), Vec2(0.0075, 0.5));
  const SolidParticles<2> one = fill<2>(thin, dx, Vec2(0, 0));
  ASSERT_EQ(one.size(), 1);
  EXPECT_NEAR(totalVolume(one), 0.0075 * 0.5, 1e-15);
}

TEST(ParticleFill, Refusals) {
  using mfwave::testing::inputErrorKey;
  const Ball<2> disc(Vec2(0, 0), 1);
  EXPECT_EQ(inputErrorKey([&] { fill<2>(HalfSpace<2>(Vec2(0, 0), Vec2(0, 1)), 0.1, Vec2(0, 0)); }), "solid");
  EXPECT_EQ(inputErrorKey([&] { fill<2>(disc, 0.0, Vec2(0, 0)); }), "spacing");
  EXPECT_EQ(inputErrorKey([&] { fill<2>(disc, 0.1, Vec2(NAN, 0)); }), "origin");
  FillOptions deep;
  deep.depth = 12;
  EXPECT_EQ(inputErrorKey([&] { fill<2>(disc, 0.1, Vec2(0, 0), deep); }), "fill.depth");
  FillOptions greedy;
  greedy.sliverFraction = 1;
  EXPECT_EQ(inputErrorKey([&] { fill<2>(disc, 0.1, Vec2(0, 0), greedy); }), "fill.sliver_fraction");
}
