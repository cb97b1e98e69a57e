// The very weak form operator as published (Ding-Long-Wu eqs. (15), (19), (21)-(22)): its
// symmetries, and its known defects measured and asserted as they are, so that a consistent
// variant that removes them shows up as a change here.

#include "BlockFixture.hpp"

#include "core/Material.hpp"
#include "methods/very_weak_sph/TractionLoad.hpp"
#include "methods/very_weak_sph/VeryWeakOperator.hpp"
#include "methods/very_weak_sph/VeryWeakSph.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace mfwave;
using mfwave::test::Block;

namespace {

VeryWeakSphOptions lame(Real lambda, Real mu) {
  VeryWeakSphOptions options;
  options.material = Material::fromLame(lambda, mu, 1);
  return options;
}

// The D x D block of row particle a times the vector field u (dof = particle * D + component).
Vec3 rowTimes(const SparseMatrix& k, Index a, const Vector& u) {
  const Vector ku = k * u;
  return ku.segment<3>(3 * a);
}

}  // namespace

TEST(VeryWeakSphOperator, InteriorBlockIsSymmetricAndEvenBoundaryBlockIsOdd) {
  const CubicSplineKernel kernel(3, 0.7);
  const Real lambda = 2, mu = 1;
  const Vec3 n(0, 0, -1);
  for (const Vec3& r : {Vec3(0.3, -0.2, 0.5), Vec3(0.9, 0.1, 0.0), Vec3(0.0, 0.0, 1.2)}) {
    const Mat3 k = veryWeakInteriorBlock<3>(kernel, lambda, mu, r);
    EXPECT_LT((k - k.transpose()).norm(), 1e-13 * k.norm());
    EXPECT_LT((k - veryWeakInteriorBlock<3>(kernel, lambda, mu, Vec3(-r))).norm(), 1e-13 * k.norm());
    const Mat3 g = veryWeakBoundaryBlock<3>(kernel, lambda, mu, r, n);
    EXPECT_LT((g + veryWeakBoundaryBlock<3>(kernel, lambda, mu, Vec3(-r), n)).norm(), 1e-13 * g.norm());
    // Gamma_ik = mu delta_ik n.grad W + mu n_i W_,k + lambda n_k W_,i, written out.
    const Vec3 w = kernel.gradient(r);
    for (int i = 0; i < 3; ++i)
      for (int k2 = 0; k2 < 3; ++k2)
        EXPECT_NEAR(g(i, k2), mu * (i == k2 ? n.dot(w) : 0.0) + mu * n[i] * w[k2] + lambda * n[k2] * w[i], 1e-12);
  }
  // The self block: Hessian of the 3-D cubic spline at 0 is -3/(pi h^5) I, so K_aa = (4 mu + lambda) of it.
  const Real h = 0.7;
  EXPECT_NEAR(veryWeakInteriorBlock<3>(kernel, lambda, mu, Vec3::Zero())(1, 1), -(4 * mu + lambda) * 3 / (M_PI * std::pow(h, 5)),
              1e-12 / std::pow(h, 5));
  // 1-D: K = (lambda + 2 mu) W'', Gamma = (lambda + 2 mu) n W'.
  const CubicSplineKernel line(1, 0.7);
  const Vec1 r(0.4);
  EXPECT_NEAR(veryWeakInteriorBlock<1>(line, lambda, mu, r)(0, 0), (lambda + 2 * mu) * line.hessian(r)(0, 0), 1e-12);
  EXPECT_NEAR(veryWeakBoundaryBlock<1>(line, lambda, mu, r, Vec1(1))(0, 0), (lambda + 2 * mu) * line.gradient(r)[0], 1e-12);
}

TEST(VeryWeakSphOperator, DeepInteriorBlocksAreSymmetric) {
  const Block<3> block(Vec3::Zero(), Vec3::Constant(4), 1.0, 2, 1.0);
  const VeryWeakSph<3> vw = assembleVeryWeakSph(block.particles, block.neighbours, block.kernel, lame(2, 1));
  const Eigen::MatrixXd k(vw.data.operatorMatrix);
  const Index a = block.find(Vec3(2, 2, 2));
  for (const Vec3& x : {Vec3(3, 2, 2), Vec3(3, 3, 1), Vec3(1, 2, 3)}) {
    const Index b = block.find(x);
    const Eigen::Matrix3d ab = k.block(3 * a, 3 * b, 3, 3);
    const Eigen::Matrix3d ba = k.block(3 * b, 3 * a, 3, 3);
    EXPECT_LT((ab - ba).norm(), 1e-13 * ab.norm());
    EXPECT_LT((ab - ab.transpose()).norm(), 1e-13 * ab.norm());
  }
  // Near the surface the boundary terms make K unsymmetric: a face row against an interior row.
  const Index face = block.find(Vec3(2, 2, 0));
  const Index below = block.find(Vec3(2, 2, 1));
  const Eigen::Matrix3d faceBelow = k.block(3 * face, 3 * below, 3, 3);
  const Eigen::Matrix3d belowFace = k.block(3 * below, 3 * face, 3, 3);
  const Real asymmetry = (faceBelow - belowFace.transpose()).norm();
  std::printf("face/interior block asymmetry %.6g\n", asymmetry);
  EXPECT_GT(asymmetry, 0.1);
}

TEST(VeryWeakSphOperator, RigidTranslationIsNotExactInTheInterior) {
  // Known defect of the published scheme: sum_b K_ab V_b != 0. On a lattice with h = dx it is
  // c I with c h^2 = -0.055923 (lambda = mu = 1; the findings say about -0.056): a spurious elastic foundation.
  for (Real h : {1.0, 0.5}) {
    const Block<3> block(Vec3::Zero(), Vec3::Constant(4 * h), h, 2, h);
    const VeryWeakSph<3> vw = assembleVeryWeakSph(block.particles, block.neighbours, block.kernel, lame(1, 1));
    const Index a = block.find(Vec3::Constant(2 * h));
    for (int axis = 0; axis < 3; ++axis) {
      Vector u = Vector::Zero(3 * block.particles.physicalCount());
      for (Index b = 0; b < block.particles.physicalCount(); ++b) u[3 * b + axis] = 1;
      const Vec3 sum = rowTimes(vw.data.operatorMatrix, a, u);
      if (axis == 0) std::printf("h = %g: interior row sum * h^2 = %.17g\n", h, sum[0] * h * h);
      EXPECT_NEAR(sum[axis] * h * h, -0.055922641601081541, 1e-12);
      for (int i = 0; i < 3; ++i) {
        if (i != axis) {
          EXPECT_NEAR(sum[i] * h * h, 0, 1e-12);
        }
      }
    }
  }
}

TEST(VeryWeakSphOperator, UniformStressPatchTestFailsByOrderOneAtTheSurface) {
  // Known defect: u = eps (x - x^a) with the matching tractions sigma n on every facet (eq. (19))
  // should give K u + f = 0 at every particle a; at the surface it does not. lambda = 2, mu = 1,
  // h = dx = 1, ghosts complete V and A. Displacement zero at x^a keeps the row-sum defect out.
  const Block<3> block(Vec3::Zero(), Vec3::Constant(4), 1.0, 2, 1.0);
  const Real lambda = 2, mu = 1;
  const VeryWeakSph<3> vw = assembleVeryWeakSph(block.particles, block.neighbours, block.kernel, lame(lambda, mu));
  Mat3 eps;
  eps << 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0;  // uniaxial strain along z
  const Mat3 sigma = lambda * eps.trace() * Mat3::Identity() + 2 * mu * eps;
  const Vector t = facetTractionsFromStress(vw.data.facets, sigma);
  auto residual = [&](const Vec3& xa) {
    const Index a = block.find(xa);
    Vector u(3 * block.particles.physicalCount());
    for (Index b = 0; b < block.particles.physicalCount(); ++b) u.segment<3>(3 * b) = eps * (block.particles.position(b) - xa);
    Vector f = Vector::Zero(u.size());
    addTractionLoad(vw.data.tractionMatrix, t, f);
    return Vec3((vw.data.operatorMatrix * u + f).segment<3>(3 * a));
  };
  const Vec3 interior = residual(Vec3(2, 2, 2));
  const Vec3 face = residual(Vec3(2, 2, 0));
  const Vec3 belowFace = residual(Vec3(2, 2, 1));
  const Vec3 edge = residual(Vec3(2, 0, 0));
  const Vec3 corner = residual(Vec3(0, 0, 0));
  std::printf("patch residual z: interior %.17g face %.17g below-face %.17g edge %.17g corner %.17g\n", interior[2],
              face[2], belowFace[2], edge[2], corner[2]);
  std::printf("edge (%.17g %.17g %.17g) corner (%.17g %.17g %.17g)\n", edge[0], edge[1], edge[2], corner[0], corner[1],
              corner[2]);
  EXPECT_LT(interior.norm(), 1e-12);                 // deep inside: exact by symmetry
  EXPECT_NEAR(face[0], 0, 1e-12);                    // the face residual is normal to the face
  EXPECT_NEAR(face[1], 0, 1e-12);
  // Measured: sigma_zz = 4; the face residual is 0.371 sigma_zz / h, the next layer's -0.124 sigma_zz / h,
  // and at the edge and corner the normal part is 1/2 and 1/4 of the face's, with tangential parts.
  EXPECT_NEAR(face[2], 1.4836258757333844, 1e-10);
  EXPECT_NEAR(belowFace[2], -0.4947365112411537, 1e-10);
  EXPECT_LT(belowFace.head<2>().norm(), 1e-12);
  EXPECT_LT((edge - Vec3(0, -0.2721655690188356, 0.74181293786669222)).norm(), 1e-10);
  EXPECT_LT((corner - Vec3(-0.13608278450941788, -0.13608278450941783, 0.37090646893334611)).norm(), 1e-10);
}

TEST(VeryWeakSphOperator, TractionLoadOfAUniformPressureIsMeasured) {
  // f_a = sum_b W_ab A_b T_b (eq. (19)). A uniform pressure 1 on the z = 0 face of a 4 x 4 x 4 block
  // (h = dx = 1) is a force of 16. Measured: the volume-weighted load sum_a V_a f_a is 5.606 (the
  // kernel spreads each facet force over the half support, sum_a W_ab V_a = 1/2 on a face), and
  // with the row factor alpha (eq. (29)) sum_a V_a alpha_a f_a is 13.76: neither is 16 on so coarse
  // a block. Asserted as measured, to show up when the load treatment changes.
  const Block<3> block(Vec3::Zero(), Vec3::Constant(4), 1.0, 2, 1.0);
  const VeryWeakSph<3> vw = assembleVeryWeakSph(block.particles, block.neighbours, block.kernel, lame(1, 1));
  const Index n = block.particles.physicalCount();
  Vector nodal = Vector::Zero(3 * n);
  for (Index a = 0; a < n; ++a)
    if (block.particles.position(a)[2] == 0) nodal[3 * a + 2] = 1;  // traction +1 (pressure) on z = 0 ...
  Vector t = facetTractionsFromNodal(vw.data.facets, nodal);
  for (Index f = 0; f < vw.data.facets.count(); ++f)                // ... on the z = 0 facets only
    if (vw.data.facets.face[static_cast<std::size_t>(f)] != 4) t.segment<3>(3 * f).setZero();
  Vector f = Vector::Zero(3 * n);
  addTractionLoad(vw.data.tractionMatrix, t, f);
  Real total = 0, corrected = 0;
  for (Index a = 0; a < n; ++a) {
    total += vw.data.volume[static_cast<std::size_t>(a)] * f[3 * a + 2];
    corrected += vw.data.alpha[static_cast<std::size_t>(a)] * vw.data.volume[static_cast<std::size_t>(a)] * f[3 * a + 2];
    EXPECT_EQ(f[3 * a], 0.0);
  }
  std::printf("traction load: sum V f = %.17g, sum alpha V f = %.17g\n", total, corrected);
  EXPECT_NEAR(total, 5.6057873564638543, 1e-10);
  EXPECT_NEAR(corrected, 13.763140410929847, 1e-10);
  // The face's facet areas add up to its area 16 (to the lattice ratio 0.99914).
  Real area = 0;
  for (Index k = 0; k < vw.data.facets.count(); ++k)
    if (vw.data.facets.face[static_cast<std::size_t>(k)] == 4) area += vw.data.facets.area[static_cast<std::size_t>(k)];
  EXPECT_NEAR(area, 16 * 0.99913890933950833, 1e-10);
}

TEST(VeryWeakSphOperator, CorrectionsCanBeSwitchedOff) {
  const Block<3> block(Vec3::Zero(), Vec3::Constant(2), 1.0, 2, 1.0);
  VeryWeakSphOptions plain = lame(1, 1);
  plain.boundaryVolumeCorrection = plain.boundaryAreaCorrection = plain.boundaryKernelCorrection = false;
  plain.boundaryIntegral = false;
  const VeryWeakSph<3> on = assembleVeryWeakSph(block.particles, block.neighbours, block.kernel, lame(1, 1));
  const VeryWeakSph<3> off = assembleVeryWeakSph(block.particles, block.neighbours, block.kernel, plain);
  const Index corner = block.find(Vec3::Zero());
  EXPECT_NEAR(off.data.volume[static_cast<std::size_t>(corner)], 8 * on.data.volume[static_cast<std::size_t>(corner)], 1e-14);
  EXPECT_NEAR(off.data.facets.area[static_cast<std::size_t>(off.data.facets.begin(corner))],
              4 * on.data.facets.area[static_cast<std::size_t>(on.data.facets.begin(corner))], 1e-14);
  EXPECT_EQ(off.system.mass().coeff(0, 0), 1.0);
  EXPECT_NEAR(on.system.mass().coeff(0, 0), 1.0 / 8, 1e-14);  // particle 0 is the corner (0,0,0)
  // Without the boundary integral the operator of a deep-interior-free block is the plain K V sum.
  EXPECT_GT((Eigen::MatrixXd(on.data.operatorMatrix) - Eigen::MatrixXd(off.data.operatorMatrix)).norm(), 1.0);
  EXPECT_LT((Eigen::MatrixXd(on.system.stiffness()) + Eigen::MatrixXd(on.data.operatorMatrix)).norm(), 1e-14);
}
