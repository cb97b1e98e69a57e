// The Lamb test's surface patch load (Ding-Long-Wu eqs. (36)-(37)) with fractional cell weights,
// and the resultant of the discrete traction load of eq. (19).

#include "BlockFixture.hpp"

#include "core/Error.hpp"
#include "methods/very_weak_sph/BoundaryFacets.hpp"
#include "methods/very_weak_sph/KernelCorrection.hpp"
#include "methods/very_weak_sph/PatchLoad.hpp"
#include "methods/very_weak_sph/StatisticalVolume.hpp"
#include "methods/very_weak_sph/TractionLoad.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numeric>

using namespace mfwave;
using mfwave::test::Block;

namespace {

constexpr int kTop = static_cast<int>(BoxFace::PlusZ);
// The section 8 block: the free surface is z = 0.
const Vec3 kPatchLower(-3.5, -3.5, -7);
const Vec3 kUpper(3.5, 3.5, 0);
// Measured (see ResultantOfTheDiscreteTractionLoad).
constexpr Real kPhysicalResultant = 0.86167836222071348;

Real sum(const std::vector<Real>& v) { return std::accumulate(v.begin(), v.end(), 0.0); }

}  // namespace

TEST(PatchLoad, SectionEightSquareGivesHalfAndQuarterCells) {
  const Real dx = 0.5;
  const ParticleSet<3> particles = makeLattice<3>(kPatchLower, kUpper, dx);
  const std::vector<Real> w =
      patchLoadWeights(particles, kTop, Vec3(0, 0, 0), Vec3(0.5, 0.5, 0), dx, kPatchLower, kUpper);
  auto at = [&](Real x, Real y) {
    for (Index a = 0; a < particles.physicalCount(); ++a)
      if ((particles.position(a) - Vec3(x, y, 0)).norm() < 1e-9) return w[static_cast<std::size_t>(a)];
    ADD_FAILURE() << "no particle at " << x << ", " << y;
    return -1.0;
  };
  EXPECT_EQ(at(0, 0), 1.0);
  for (const auto& [x, y] : {std::pair{0.5, 0.0}, {-0.5, 0.0}, {0.0, 0.5}, {0.0, -0.5}}) EXPECT_EQ(at(x, y), 0.5);
  for (const auto& [x, y] : {std::pair{0.5, 0.5}, {-0.5, 0.5}, {0.5, -0.5}, {-0.5, -0.5}}) EXPECT_EQ(at(x, y), 0.25);
  int loaded = 0;
  for (Real v : w) loaded += v > 0;
  EXPECT_EQ(loaded, 9);
  EXPECT_EQ(sum(w) * dx * dx, 1.0);  // the area of the square, exactly
  // Particles below the surface are never loaded, even right under the patch.
  for (Index a = 0; a < particles.physicalCount(); ++a)
    if (particles.position(a)[2] < -1e-9) {
      EXPECT_EQ(w[static_cast<std::size_t>(a)], 0.0);
    }
}

TEST(PatchLoad, WeightsIntegrateToThePatchAreaOnAnyLatticeAndPatch) {
  for (Real dx : {0.5, 0.25, 0.125}) {
    const ParticleSet<3> particles = makeLattice<3>(kPatchLower, kUpper, dx);
    const Real centred = sum(patchLoadWeights(particles, kTop, Vec3(0, 0, 0), Vec3(0.5, 0.5, 9), dx, kPatchLower, kUpper));
    EXPECT_NEAR(centred * dx * dx, 1.0, 1e-14) << dx;
    // Not aligned with the lattice: 4 * 0.61 * 0.37 = 0.9028.
    const Real skew =
        sum(patchLoadWeights(particles, kTop, Vec3(0.3, -0.7, 0), Vec3(0.61, 0.37, 0), dx, kPatchLower, kUpper));
    EXPECT_NEAR(skew * dx * dx, 0.9028, 1e-14) << dx;
    // Over the edge x = 3.5: only [2.7, 3.5] x [-0.5, 0.5] of the face is loaded, area 0.8.
    const Real clipped =
        sum(patchLoadWeights(particles, kTop, Vec3(3.2, 0, 0), Vec3(0.5, 0.5, 0), dx, kPatchLower, kUpper));
    EXPECT_NEAR(clipped * dx * dx, 0.8, 1e-14) << dx;
    // The whole face: every cell counts once, edges half, corners a quarter.
    const Real whole = sum(patchLoadWeights(particles, kTop, Vec3(0, 0, 0), Vec3(10, 10, 0), dx, kPatchLower, kUpper));
    EXPECT_NEAR(whole * dx * dx, 49.0, 1e-12) << dx;
  }
}

TEST(PatchLoad, EdgeParticlesLoadOnlyTheirFacetOnTheLoadedFace) {
  const Real dx = 0.5;
  const Block<3> block(kPatchLower, kUpper, dx, 2, dx);
  const BoundaryFacets<3> facets = boundaryFacets(block.particles, block.neighbours, block.kernel, true);
  const std::vector<Real> w =
      patchLoadWeights(block.particles, kTop, Vec3(3.2, 0, 0), Vec3(0.5, 0.5, 0), dx, kPatchLower, kUpper);
  const Vec3 traction(0, 0, -1);
  const Vector t = patchFacetTractions(facets, kTop, w, traction);
  const Index edge = block.find(Vec3(3.5, 0, 0));
  EXPECT_EQ(w[static_cast<std::size_t>(edge)], 0.5);  // half a cell, fully covered
  ASSERT_EQ(facets.end(edge) - facets.begin(edge), 2);
  for (Index f = facets.begin(edge); f < facets.end(edge); ++f) {
    const Vec3 tf = t.segment<3>(3 * f);
    const Vec3 expected = facets.face[static_cast<std::size_t>(f)] == kTop ? Vec3(0, 0, -0.5) : Vec3(0, 0, 0);
    EXPECT_EQ(tf, expected);
  }
  // Loading by nodal tractions instead would put the same traction on the +x facet as well.
  Vector nodal = Vector::Zero(3 * block.particles.physicalCount());
  for (Index a = 0; a < block.particles.physicalCount(); ++a)
    nodal.segment<3>(3 * a) = w[static_cast<std::size_t>(a)] * traction;
  const Vector both = facetTractionsFromNodal(facets, nodal);
  EXPECT_GT((both - t).cwiseAbs().maxCoeff(), 0.4);
  EXPECT_THROW((void)patchFacetTractions(facets, kTop, std::vector<Real>(3, 1.0), traction), InputError);
  EXPECT_THROW((void)patchLoadWeights(block.particles, 6, Vec3(0, 0, 0), Vec3(1, 1, 1), dx, kPatchLower, kUpper),
               InputError);
}

TEST(PatchLoad, ResultantOfTheDiscreteTractionLoad) {
  // f = T t (eq. (19)) is a force per unit volume in rho u''_a = (K u)_a + f_a; with eqs. (28)-(29)
  // the row reads (rho / alpha_a) u''_a = (K u + f)_a. Its resultant depends on the mass each
  // particle is given:
  //  - the quadrature of the surface integral, sum_f A_f t_f = (A / dx^2) x exact;
  //  - on the physical masses rho V_a (u''_a = alpha_a f_a / rho): sum_a alpha_a V_a f_a;
  //  - on the lumped masses rho V_a / alpha_a, whose momentum the conservative smoothing conserves
  //    exactly: sum_a V_a f_a.
  // sum_a W_ab V_a over the physical a is s_b = FV_b = 1/2 for a face particle b (ghost-completed
  // lattice), so the lumped resultant is exactly half the quadrature one. The physical one weighs
  // each a by alpha_a V_a: V_lattice on the face and deeper down, but more one layer below the face,
  // where alpha > 1 because the face neighbours have half volumes; measured 0.8624 of the quadrature
  // (0.8503 if alpha_a V_a were V_lattice everywhere).
  const Real dx = 0.5;
  const Block<3> block(kPatchLower, kUpper, dx, 2, dx);
  const Index n = block.particles.physicalCount();
  const std::vector<Real> volume = statisticalVolumes(block.particles, block.neighbours, block.kernel, true);
  const std::vector<Real> alpha = kernelCorrectionFactors(block.particles, block.neighbours, block.kernel, volume, true);
  const BoundaryFacets<3> facets = boundaryFacets(block.particles, block.neighbours, block.kernel, true);
  const SparseMatrix tractionMatrix = assembleTractionMatrix(block.particles, block.neighbours, block.kernel, facets);
  const std::vector<Real> w =
      patchLoadWeights(block.particles, kTop, Vec3(0, 0, 0), Vec3(0.5, 0.5, 0), dx, kPatchLower, kUpper);
  const Vec3 traction(0, 0, -1);  // a unit pressure: exact resultant (0, 0, -1) over the unit square
  const Vector t = patchFacetTractions(facets, kTop, w, traction);
  Vector f = Vector::Zero(3 * n);
  addTractionLoad(tractionMatrix, t, f);

  Vec3 quadrature = Vec3::Zero();
  for (Index k = 0; k < facets.count(); ++k) quadrature += facets.area[static_cast<std::size_t>(k)] * t.segment<3>(3 * k);
  Vec3 physical = Vec3::Zero(), lumped = Vec3::Zero();
  for (Index a = 0; a < n; ++a) {
    const auto i = static_cast<std::size_t>(a);
    physical += alpha[i] * volume[i] * f.segment<3>(3 * a);
    lumped += volume[i] * f.segment<3>(3 * a);
  }
  std::printf("resultant / exact: quadrature %.12f, on physical masses %.12f, on lumped masses %.12f\n",
              -quadrature[2], -physical[2], -lumped[2]);
  EXPECT_NEAR(quadrature[0], 0.0, 1e-15);
  EXPECT_NEAR(-quadrature[2], 0.99913890933950833, 1e-13);  // kLatticeArea of VolumeAndAreaTest.cpp
  EXPECT_NEAR(-lumped[2], 0.99913890933950833 / 2, 1e-13);
  EXPECT_NEAR(-physical[2], kPhysicalResultant, 1e-12);
  EXPECT_NEAR(physical[0], 0.0, 1e-15);
  EXPECT_NEAR(physical[1], 0.0, 1e-15);
}
