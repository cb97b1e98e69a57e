// The transmitting boundary of Ding-Long-Wu eqs. (31)-(32) as a damping matrix: its structure, its
// entries on a lattice block against independent sums, the local frame of the dashpots, and input
// checks.

#include "BlockFixture.hpp"
#include "solvers/DenseEigenproblems.hpp"

#include "core/Error.hpp"
#include "core/Material.hpp"
#include "kernels/PlaneIntegral.hpp"
#include "methods/very_weak_sph/TransmittingBoundary.hpp"
#include "methods/very_weak_sph/VeryWeakSph.hpp"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace mfwave;
using mfwave::test::Block;

namespace {

// sum_b W_ab A_b over every physical particle b with a facet on `face`, by brute force over all
// particles (no neighbour list), the weight of eq. (32).
Real independentFaceSum(const Block<3>& block, const BoundaryFacets<3>& facets, Index a, int face) {
  Real sum = 0;
  const Vec3 xa = block.particles.position(a);
  for (Index b = 0; b < block.particles.physicalCount(); ++b)
    for (Index g = facets.begin(b); g < facets.end(b); ++g)
      if (facets.face[static_cast<std::size_t>(g)] == face)
        sum += block.kernel.value(Vec3(xa - block.particles.position(b))) * facets.area[static_cast<std::size_t>(g)];
  return sum;
}

Mat3 diagonalBlock(const SparseMatrix& c, Index a) { return Mat3(Eigen::MatrixXd(c).block<3, 3>(3 * a, 3 * a)); }

}  // namespace

TEST(TransmittingBoundary, ParticleLumpingEntriesOnALatticeBlock) {
  // A 4 x 4 x 4 block at spacing 0.5 (9^3 = 729 particles), two ghost layers, h = dx, lambda = mu =
  // rho = 1 (c_p = sqrt(3), c_s = 1). Transmitting: -z and -x; +x is free.
  const Real dx = 0.5;
  const Block<3> block(Vec3::Zero(), Vec3::Constant(4), dx, 2, dx);
  const VeryWeakSph<3> vw = assembleVeryWeakSph(block.particles, block.neighbours, block.kernel, VeryWeakSphOptions{});
  const Material material = Material::fromLame(1, 1, 1);
  const std::uint8_t mask = faceBit(BoxFace::MinusZ) | faceBit(BoxFace::MinusX);
  const SparseMatrix c = assembleTransmittingDamping(block.particles, block.neighbours, block.kernel, vw.data.facets,
                                                     material, mask, DashpotLumping::Particle);
  const Real cp = std::sqrt(3.0), cs = 1.0;
  const int minusZ = static_cast<int>(BoxFace::MinusZ), minusX = static_cast<int>(BoxFace::MinusX);

  // The centre of the -z face: zz = rho c_p sum_b W_ab A_b, xx = yy = rho c_s times the same.
  const Index face = block.find(Vec3(2, 2, 0));
  const Real faceSum = independentFaceSum(block, vw.data.facets, face, minusZ);
  const Mat3 faceBlock = diagonalBlock(c, face);
  std::printf("face (2,2,0): sum W A = %.15f, 1/S = %.15f, C diag = (%.12f, %.12f, %.12f)\n", faceSum,
              planeIntegralThroughCentre(block.kernel), faceBlock(0, 0), faceBlock(1, 1), faceBlock(2, 2));
  EXPECT_NEAR(faceBlock(2, 2), cp * faceSum, 1e-12);
  EXPECT_NEAR(faceBlock(0, 0), cs * faceSum, 1e-12);
  EXPECT_NEAR(faceBlock(1, 1), cs * faceSum, 1e-12);
  EXPECT_EQ(faceBlock(0, 1), 0.0);
  EXPECT_EQ(faceBlock(0, 2), 0.0);
  // On the flat face every neighbour has the same plane sum, so sum_b W_ab A_b = planeSum / (S planeSum)
  // = 1/S = 7/(10h) (eq. (40)): the dashpot is rho c_p / S.
  EXPECT_NEAR(faceSum, 0.7 / dx, 1e-12);
  EXPECT_NEAR(faceBlock(2, 2), 2.4248711305964283, 1e-12);

  // The -z/-x edge: the sum of the two dashpots, each in its own frame, with the edge area fraction
  // FA = 1/2 in its neighbours' facets.
  const Index edge = block.find(Vec3(0, 2, 0));
  const Real sumZ = independentFaceSum(block, vw.data.facets, edge, minusZ);
  const Real sumX = independentFaceSum(block, vw.data.facets, edge, minusX);
  const Mat3 edgeBlock = diagonalBlock(c, edge);
  std::printf("edge (0,2,0): sums (-z, -x) = (%.15f, %.15f), C diag = (%.12f, %.12f, %.12f)\n", sumZ, sumX,
              edgeBlock(0, 0), edgeBlock(1, 1), edgeBlock(2, 2));
  EXPECT_NEAR(sumZ, sumX, 1e-14);  // the two faces are alike by symmetry
  EXPECT_NEAR(edgeBlock(0, 0), cs * sumZ + cp * sumX, 1e-12);
  EXPECT_NEAR(edgeBlock(1, 1), cs * sumZ + cs * sumX, 1e-12);
  EXPECT_NEAR(edgeBlock(2, 2), cp * sumZ + cs * sumX, 1e-12);
  // The edge facets have FA = 1/2 (eq. (26)) and ghosts complete their plane sums: FA / S = 0.35 / h.
  EXPECT_NEAR(sumZ, 0.5 * 0.7 / dx, 1e-12);

  // The -z/+x edge (+x free): the -z dashpot only.
  const Index freeEdge = block.find(Vec3(4, 2, 0));
  const Real sumFree = independentFaceSum(block, vw.data.facets, freeEdge, minusZ);
  const Mat3 freeBlock = diagonalBlock(c, freeEdge);
  EXPECT_NEAR(sumFree, sumZ, 1e-14);
  EXPECT_NEAR(freeBlock(0, 0), cs * sumFree, 1e-12);
  EXPECT_NEAR(freeBlock(2, 2), cp * sumFree, 1e-12);

  // Block-diagonal, symmetric; nothing on particles off the transmitting faces.
  for (int k = 0; k < c.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(c, k); it; ++it) EXPECT_EQ(it.row() / 3, it.col() / 3);
  EXPECT_EQ((c - SparseMatrix(c.transpose())).norm(), 0.0);
  const Index inside = block.find(Vec3(2, 2, 0.5));
  EXPECT_EQ(diagonalBlock(c, inside).norm(), 0.0);
}

TEST(TransmittingBoundary, ParticleLumpingIsPositiveSemiDefiniteAndConsistentCouplesNeighbours) {
  // A 2 x 2 x 2 block at spacing 0.5 (125 particles), every face transmitting.
  const Real dx = 0.5;
  const Block<3> block(Vec3::Zero(), Vec3::Constant(2), dx, 2, dx);
  const VeryWeakSph<3> vw = assembleVeryWeakSph(block.particles, block.neighbours, block.kernel, VeryWeakSphOptions{});
  const Material material = Material::fromLame(1, 1, 1);
  const SparseMatrix particle = assembleTransmittingDamping(block.particles, block.neighbours, block.kernel,
                                                            vw.data.facets, material, allFaces(3));
  const Eigen::VectorXd eigen = symmetricEigenvalues(Eigen::MatrixXd(particle));
  const Real smallest = eigen.minCoeff();
  const Real largest = eigen.maxCoeff();
  std::printf("particle lumping, 2x2x2 block, all faces: eigenvalues in [%.6f, %.6f]\n", smallest, largest);
  EXPECT_EQ(smallest, 0.0);  // the 27 interior particles have no dashpot
  EXPECT_NEAR(largest, std::sqrt(3.0) * 0.7 / dx, 1e-12);  // a face particle's rho c_p / S

  // Consistent: couples neighbours, reaches interior particles, is not symmetric. On the face centre
  // (2 h from every edge) its row sum is the particle-lumped dashpot.
  const SparseMatrix consistent = assembleTransmittingDamping(block.particles, block.neighbours, block.kernel,
                                                              vw.data.facets, material, allFaces(3),
                                                              DashpotLumping::Consistent);
  const Index face = block.find(Vec3(1, 1, 0));
  const Vector ones = Vector::Ones(consistent.cols());
  const Vector rowSums = consistent * ones;
  const Mat3 faceBlock = diagonalBlock(particle, face);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(rowSums[3 * face + i], faceBlock(i, i), 1e-12);
  const Index below = block.find(Vec3(1, 1, 0.5));
  std::printf("consistent: row sums at face centre %.12f (zz), one layer in %.12f (zz), asymmetry %.6f\n",
              rowSums[3 * face + 2], rowSums[3 * below + 2],
              (consistent - SparseMatrix(consistent.transpose())).norm());
  EXPECT_NEAR(rowSums[3 * below + 2], 0.518076140433, 1e-11);
  EXPECT_GT((consistent - SparseMatrix(consistent.transpose())).norm(), 0.1);
}

TEST(TransmittingBoundary, BadInputNamesItsKey) {
  const Block<2> block(Vec2::Zero(), Vec2::Constant(2), 0.5, 2, 0.5);
  const VeryWeakSph<2> vw = assembleVeryWeakSph(block.particles, block.neighbours, block.kernel, VeryWeakSphOptions{});
  const Material material = Material::fromLame(1, 1, 1);
  try {
    assembleTransmittingDamping(block.particles, block.neighbours, block.kernel, vw.data.facets, material,
                                faceBit(BoxFace::MinusZ));
    FAIL() << "a -z face in 2-D was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "transmitting_faces");
  }
  const Block<2> other(Vec2::Zero(), Vec2::Constant(1), 0.5, 2, 0.5);
  try {
    assembleTransmittingDamping(other.particles, other.neighbours, other.kernel, vw.data.facets, material,
                                faceBit(BoxFace::MinusY));
    FAIL() << "facets of another particle set were accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "facets");
  }
}
