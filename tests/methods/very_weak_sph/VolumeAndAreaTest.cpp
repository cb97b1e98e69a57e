// Statistical volumes (Ding-Long-Wu eqs. (4), (24)-(25)) and boundary areas (eqs. (20), (26)-(27))
// on lattice blocks whose sums are completed by ghost layers.

#include "BlockFixture.hpp"

#include "core/Error.hpp"
#include "kernels/CubicSplineKernel.hpp"
#include "methods/very_weak_sph/BoundaryFacets.hpp"
#include "methods/very_weak_sph/KernelCorrection.hpp"
#include "methods/very_weak_sph/StatisticalVolume.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace mfwave;
using mfwave::test::Block;

namespace {

// Full-lattice sums of the 3-D cubic spline with h = dx, measured (they are not 1/dx^3, 1/dx^2):
// V = 1 / sum_b W_ab over the whole lattice, and A = 1 / (S sum_b W_ab) over a whole lattice plane.
constexpr Real kLatticeVolume = 1.0000275346670939;  // V / dx^3 (sum_b W_ab dx^3 = 0.9999725)
constexpr Real kLatticeArea = 0.99913890933950833;   // A / dx^2 (S sum_plane W dx^2 = 1.000862)

}  // namespace

TEST(VeryWeakSphGeometry, SurfaceScaleOfTheCubicSplineIsTenHOverSeven) {
  // Ding-Long-Wu eq. (40).
  for (Real h : {0.5, 1.0, 2.5}) EXPECT_NEAR(surfaceScale(CubicSplineKernel(3, h)), 10 * h / 7, 1e-14 * h);
  // 1-D: the "plane" is a point, S = 1 / W(0).
  EXPECT_NEAR(surfaceScale(CubicSplineKernel(1, 0.5)), 1 / CubicSplineKernel(1, 0.5).value(0.0), 1e-14);
}

TEST(VeryWeakSphGeometry, VolumeFractionsFollowTheFaceMask) {
  const Block<3> block(Vec3::Zero(), Vec3::Constant(3), 1.0, 2, 1.0);
  const std::vector<Real> on = volumeFractions(block.particles, true);
  const std::vector<Real> off = volumeFractions(block.particles, false);
  EXPECT_EQ(on[static_cast<std::size_t>(block.find(Vec3(1, 1, 1)))], 1.0);
  EXPECT_EQ(on[static_cast<std::size_t>(block.find(Vec3(1, 2, 0)))], 0.5);
  EXPECT_EQ(on[static_cast<std::size_t>(block.find(Vec3(0, 2, 3)))], 0.25);
  EXPECT_EQ(on[static_cast<std::size_t>(block.find(Vec3(3, 0, 3)))], 0.125);
  for (Real f : off) EXPECT_EQ(f, 1.0);
}

TEST(VeryWeakSphGeometry, GhostCompletedVolumesAreFractionsOfTheLatticeVolume) {
  // h = dx = 0.5: every particle's Shepard sum is the full-lattice sum, so V_a = FV_a V_lattice with
  // V_lattice = kLatticeVolume dx^3 (0.0028 % above dx^3).
  const Real dx = 0.5;
  const Block<3> block(Vec3::Zero(), Vec3::Constant(3), dx, 2, dx);
  const std::vector<Real> volume = statisticalVolumes(block.particles, block.neighbours, block.kernel, true);
  const Real lattice = kLatticeVolume * dx * dx * dx;
  EXPECT_NEAR(volume[static_cast<std::size_t>(block.find(Vec3(1.5, 1.5, 1.5)))], lattice, 1e-13 * lattice);
  EXPECT_NEAR(volume[static_cast<std::size_t>(block.find(Vec3(1, 0.5, 1.5)))], lattice, 1e-13 * lattice);
  EXPECT_NEAR(volume[static_cast<std::size_t>(block.find(Vec3(1.5, 1.5, 0)))], lattice / 2, 1e-13 * lattice);
  EXPECT_NEAR(volume[static_cast<std::size_t>(block.find(Vec3(3, 1.5, 0)))], lattice / 4, 1e-13 * lattice);
  EXPECT_NEAR(volume[static_cast<std::size_t>(block.find(Vec3(3, 3, 0)))], lattice / 8, 1e-13 * lattice);
  // The lattice sum is within 1e-4 of the continuum 1 / dx^3, not equal to it.
  EXPECT_NEAR(kLatticeVolume, 1.0, 3e-5);
  EXPECT_GT(std::abs(kLatticeVolume - 1.0), 2e-5);

  // Without ghosts the boundary sums are truncated: a corner sees about an eighth of the support
  // plus its own centre weight, so with the correction off its volume is 1.65 dx^3.
  const Block<3> bare(Vec3::Zero(), Vec3::Constant(3), dx, 0, dx);
  const std::vector<Real> plain = statisticalVolumes(bare.particles, bare.neighbours, bare.kernel, false);
  const Real corner = plain[static_cast<std::size_t>(bare.find(Vec3(0, 0, 0)))] / (dx * dx * dx);
  EXPECT_NEAR(corner, 1.6486392468104527, 1e-12);
}

TEST(VeryWeakSphGeometry, GhostCompletedFaceAreasAreFractionsOfDxSquared) {
  // h = dx: A = FA / (S sum_plane W) = FA kLatticeArea dx^2 on every facet (0.086 % below dx^2).
  const Real dx = 0.5;
  const Block<3> block(Vec3::Zero(), Vec3::Constant(3), dx, 2, dx);
  const BoundaryFacets<3> facets = boundaryFacets(block.particles, block.neighbours, block.kernel, true);
  const Real lattice = kLatticeArea * dx * dx;
  auto facetArea = [&](const Vec3& x, int face) {
    const Index a = block.find(x);
    for (Index f = facets.begin(a); f < facets.end(a); ++f)
      if (facets.face[static_cast<std::size_t>(f)] == face) return facets.area[static_cast<std::size_t>(f)];
    ADD_FAILURE() << "no facet on face " << face;
    return 0.0;
  };
  const Index faceParticle = block.find(Vec3(1.5, 1.5, 0));
  ASSERT_EQ(facets.end(faceParticle) - facets.begin(faceParticle), 1);
  EXPECT_EQ(facets.normal[static_cast<std::size_t>(facets.begin(faceParticle))], Vec3(0, 0, -1));
  EXPECT_NEAR(facetArea(Vec3(1.5, 1.5, 0), 4), lattice, 1e-13 * lattice);
  EXPECT_NEAR(facetArea(Vec3(1.5, 1.5, 0), 4), dx * dx, 1e-3 * dx * dx);
  EXPECT_NEAR(facetArea(Vec3(3, 1.5, 0), 4), lattice / 2, 1e-13 * lattice);  // edge: two facets
  EXPECT_NEAR(facetArea(Vec3(3, 1.5, 0), 1), lattice / 2, 1e-13 * lattice);
  EXPECT_NEAR(facetArea(Vec3(0, 3, 0), 0), lattice / 4, 1e-13 * lattice);    // corner: three facets
  EXPECT_NEAR(facetArea(Vec3(0, 3, 0), 3), lattice / 4, 1e-13 * lattice);
  EXPECT_NEAR(facetArea(Vec3(0, 3, 0), 5 - 1), lattice / 4, 1e-13 * lattice);
  EXPECT_EQ(facets.count(), 6 * 5 * 5 + 12 * 5 * 2 + 8 * 3);  // face, edge, corner facets of a 7^3 block
}

TEST(VeryWeakSphGeometry, KernelCorrectionUndoesTheVolumeFraction) {
  // With ghost-completed volumes, sum_b W_ab V_b over the physical neighbours is FV_a exactly (the
  // body cuts a lattice-symmetric support in half per face), so alpha_a = 1 / FV_a: 1, 2, 4, 8.
  const Real dx = 0.5;
  const Block<3> block(Vec3::Zero(), Vec3::Constant(3), dx, 2, dx);
  const std::vector<Real> volume = statisticalVolumes(block.particles, block.neighbours, block.kernel, true);
  const std::vector<Real> alpha = kernelCorrectionFactors(block.particles, block.neighbours, block.kernel, volume, true);
  const Real inside = alpha[static_cast<std::size_t>(block.find(Vec3(1.5, 1.5, 1.5)))];
  const Real face = alpha[static_cast<std::size_t>(block.find(Vec3(1.5, 1.5, 0)))];
  const Real edge = alpha[static_cast<std::size_t>(block.find(Vec3(0, 1.5, 3)))];
  const Real corner = alpha[static_cast<std::size_t>(block.find(Vec3(0, 0, 0)))];
  EXPECT_NEAR(inside, 1.0, 1e-13);
  EXPECT_NEAR(face, 2.0, 1e-13);
  EXPECT_NEAR(edge, 4.0, 1e-13);
  EXPECT_NEAR(corner, 8.0, 1e-13);
  const std::vector<Real> off = kernelCorrectionFactors(block.particles, block.neighbours, block.kernel, volume, false);
  EXPECT_EQ(off[static_cast<std::size_t>(block.find(Vec3(0, 0, 0)))], 1.0);
}

TEST(VeryWeakSphGeometry, RejectsAKernelOfTheWrongDimension) {
  const Block<3> block(Vec3::Zero(), Vec3::Constant(1), 0.5, 0, 0.5);
  try {
    (void)statisticalVolumes(block.particles, block.neighbours, CubicSplineKernel(2, 0.5), true);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "dimension");
  }
}
