// The Galerkin variant (GalerkinLattice.hpp) is stable by construction: K symmetric positive
// semi-definite with exactly the rigid-body null space, the interior symbol non-negative at every
// wavenumber, the central-difference energy conserved on a free block and never raised by the
// dashpots. Its rows are exact for linear fields everywhere and for quadratic ones at interior and
// face particles (not at 2-D corners and 3-D edges and corners: 0.177 of the cancelling terms).

#include "numerics/StableTimeStep.hpp"
#include "core/Error.hpp"
#include "integrators/CentralDifference.hpp"
#include "kernels/CubicSplineKernel.hpp"
#include "methods/very_weak_sph/GalerkinLattice.hpp"
#include "methods/very_weak_sph/PatchLoad.hpp"
#include "methods/very_weak_sph/QuadraticMonomials.hpp"
#include "methods/very_weak_sph/TransmittingBoundary.hpp"
#include "methods/very_weak_sph/VeryWeakSph.hpp"
#include "particles/BoxFace.hpp"
#include "particles/Lattice.hpp"
#include "solvers/DenseEigenproblems.hpp"

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <iostream>
#include <random>

namespace mfwave {
namespace {

const Material kGalerkinMaterial = Material::fromLame(2.0, 1.0, 1.3);

template <int D>
VeryWeakSph<D> galerkin(const ParticleSet<D>& particles, const Material& material = kGalerkinMaterial) {
  VeryWeakSphOptions options;
  options.variant = VeryWeakSphVariant::Galerkin;
  options.material = material;
  return assembleVeryWeakSph<D>(particles, NeighbourList(), CubicSplineKernel(D, 1.0), options);
}

template <int D>
ParticleSet<D> block(int intervals, Real dx) {
  Vec<D> upper;
  for (int a = 0; a < D; ++a) upper[a] = dx * (intervals + a);  // unequal sides
  return makeLattice<D>(Vec<D>::Zero(), upper, dx);
}

template <int D>
void checkSymmetricWithRigidNullSpace(int intervals) {
  const ParticleSet<D> particles = block<D>(intervals, 0.7);
  VeryWeakSph<D> method = galerkin(particles);
  const SparseMatrix& k = method.system.stiffness();
  EXPECT_EQ(SparseMatrix(k - SparseMatrix(k.transpose())).norm(), 0.0) << "K must be exactly symmetric";
  const Eigen::MatrixXd dense = Eigen::MatrixXd(k);
  const Eigen::VectorXd m = Eigen::VectorXd(method.system.mass().diagonal());
  ASSERT_TRUE((m.array() > 0).all());
  const Eigen::VectorXd s = m.cwiseSqrt().cwiseInverse();
  const Eigen::VectorXd eig = symmetricEigenvalues(s.asDiagonal() * dense * s.asDiagonal());
  const Real largest = eig.maxCoeff();
  EXPECT_GE(eig.minCoeff(), -1e-12 * largest);
  const int rigid = D == 1 ? 1 : (D == 2 ? 3 : 6);
  int zero = 0;
  for (Index i = 0; i < eig.size(); ++i) zero += std::abs(eig[i]) < 1e-10 * largest;
  EXPECT_EQ(zero, rigid) << "null space other than the rigid-body modes";
  // the next mode is well away from round-off
  std::vector<Real> sorted(eig.data(), eig.data() + eig.size());
  std::sort(sorted.begin(), sorted.end());
  EXPECT_GT(sorted[static_cast<std::size_t>(rigid)], 1e-4 * largest);
}

TEST(GalerkinLattice, StiffnessIsSymmetricPositiveSemiDefiniteWithOnlyRigidModesInItsNullSpace) {
  checkSymmetricWithRigidNullSpace<1>(9);
  checkSymmetricWithRigidNullSpace<2>(6);
  checkSymmetricWithRigidNullSpace<3>(4);
}

// rho V_a u''_a = -(K u)_a + (T t)_a must equal V_a div sigma(x_a) for every quadratic field with its
// tractions t_f = sigma(x_f) n_f, at every particle. Returns the largest relative residual per kind
// (number of faces the particle lies on) over the fields of total degree `degree`.
template <int D>
std::vector<Real> galerkinPatchResiduals(int intervals, int degree) {
  const ParticleSet<D> particles = block<D>(intervals, 0.5);
  VeryWeakSph<D> method = galerkin(particles);
  const Index n = particles.physicalCount();
  const Real lambda = kGalerkinMaterial.lambda(), mu = kGalerkinMaterial.mu();
  const Vec<D> c = Vec<D>::Constant(0.4);
  std::vector<Real> worst(D + 1, 0.0);
  // monomials (x - c)^e with |e| <= 2 in component k
  const QuadraticMonomials<D> monomials;  // m(x - c) with |e| <= 2, value, gradient and Hessian
  for (int m = 0; m < QuadraticMonomials<D>::count; ++m) {
    int total = 0;
    for (const int power : monomials.exponents(m)) total += power;
    if (total != degree) continue;
    const Mat<D> hessian = monomials.hessian(m);
    for (int k = 0; k < D; ++k) {
      auto sigma = [&](const Vec<D>& x) {
        Eigen::Matrix<Real, D, D> grad = Eigen::Matrix<Real, D, D>::Zero();  // du_i / dx_j
        grad.row(k) = monomials.gradient(m, x - c).transpose();
        const Eigen::Matrix<Real, D, D> strain = 0.5 * (grad + grad.transpose());
        return Eigen::Matrix<Real, D, D>(lambda * strain.trace() * Eigen::Matrix<Real, D, D>::Identity() + 2 * mu * strain);
      };
      Vec<D> divergence;  // (lambda + mu) d_i d_k m + mu delta_ik Lap m
      for (int i = 0; i < D; ++i) divergence[i] = (lambda + mu) * hessian(i, k) + (i == k ? mu * hessian.trace() : 0);
      Vector u = Vector::Zero(D * n), t = Vector::Zero(D * method.data.facets.count()),
             tAbs = Vector::Zero(D * method.data.facets.count());
      for (Index a = 0; a < n; ++a) u[D * a + k] = monomials.value(m, particles.position(a) - c);
      for (Index f = 0; f < method.data.facets.count(); ++f) {
        const auto fi = static_cast<std::size_t>(f);
        const Vec<D> x = particles.position(method.data.facets.particle[fi]);
        t.template segment<D>(D * f) = sigma(x) * method.data.facets.normal[fi];
        tAbs.template segment<D>(D * f) = sigma(x).cwiseAbs() * method.data.facets.normal[fi].cwiseAbs();
      }
      const SparseMatrix& K = method.system.stiffness();
      const SparseMatrix& T = method.data.tractionMatrix;
      const Vector lhs = -(K * u) + T * t;
      const Vector scale = SparseMatrix(K.cwiseAbs()) * u.cwiseAbs() + SparseMatrix(T.cwiseAbs()) * tAbs;
      for (Index a = 0; a < n; ++a) {
        const Real volume = method.data.volume[static_cast<std::size_t>(a)];
        for (int i = 0; i < D; ++i) {
          const Real rhs = volume * divergence[i];
          const Real r = std::abs(lhs[D * a + i] - rhs) / (scale[D * a + i] + std::abs(rhs) + 1e-300);
          Real& w = worst[static_cast<std::size_t>(particles.facetCount(a))];
          w = std::max(w, r);
        }
      }
    }
  }
  return worst;
}

// Translation and uniform strain with its tractions: exact at every particle in 1-, 2- and 3-D.
// Quadratic fields: exact in 1-D and at interior and face particles; at 2-D corners and 3-D edges
// and corners the mixed terms int d_y W_a C d_x (u - u_h) (u_h the tent interpolant of u, whose
// error is a bubble along x) do not vanish: int W_0' dy = -1 at a face and int W_0 (u - u_h)' dx
// != 0 at the end of the x line. The row misses by 0.177 of its cancelling terms. This is the Galerkin variant's known gap against the consistent variant
// (docs/theory/very-weak-sph.md); the test pins it so that a change shows.
TEST(GalerkinLattice, RowsAreExactForLinearFieldsEverywhereAndForQuadraticsInTheInterior) {
  for (int degree = 0; degree <= 1; ++degree) {
    for (const Real r : galerkinPatchResiduals<1>(8, degree)) EXPECT_LT(r, 1e-13);
    for (const Real r : galerkinPatchResiduals<2>(5, degree)) EXPECT_LT(r, 1e-13);
    for (const Real r : galerkinPatchResiduals<3>(4, degree)) EXPECT_LT(r, 1e-13);
  }
  for (const Real r : galerkinPatchResiduals<1>(8, 2)) EXPECT_LT(r, 1e-13);
  const std::vector<Real> r2 = galerkinPatchResiduals<2>(5, 2), r3 = galerkinPatchResiduals<3>(4, 2);
  EXPECT_LT(r2[0], 1e-13);
  EXPECT_LT(r3[0], 1e-13);
  EXPECT_LT(r2[1], 1e-13);
  EXPECT_LT(r3[1], 1e-13);
  const Real boundary2 = r2[2];
  const Real boundary3 = std::max(r3[2], r3[3]);
  EXPECT_GT(boundary2, 0.1) << r2[1] << ' ' << r2[2];
  EXPECT_LT(boundary2, 0.2);
  EXPECT_GT(boundary3, 0.1) << r3[1] << ' ' << r3[2] << ' ' << r3[3];
  EXPECT_LT(boundary3, 0.2) << r3[1] << ' ' << r3[2] << ' ' << r3[3];
  std::cout << "quadratic patch residual at 2-D face/corner " << r2[1] << ' ' << r2[2] << ", 3-D face/edge/corner "
            << r3[1] << ' ' << r3[2] << ' ' << r3[3] << '\n';
}

// The symbol of an interior row, omega^2(k) = eigenvalues of sum_b K_ab e^{i k.(x_b - x_a)} / M_a,
// over the whole Brillouin zone (n^D wavenumbers of the periodic lattice grid).
template <int D>
void checkInteriorSymbol(int n) {
  const ParticleSet<D> particles = makeLattice<D>(Vec<D>::Zero(), Vec<D>::Constant(4.0), 1.0);
  VeryWeakSph<D> method = galerkin(particles);
  Index centre = -1;
  for (Index a = 0; a < particles.physicalCount(); ++a)
    if ((particles.position(a) - Vec<D>::Constant(2.0)).norm() < 1e-12) centre = a;
  ASSERT_GE(centre, 0);
  const SparseMatrix& K = method.system.stiffness();
  const Real mass = method.system.mass().coeff(static_cast<int>(D * centre), static_cast<int>(D * centre));
  Real smallest = 0, largest = 0;
  Index count = 1;
  for (int a = 0; a < D; ++a) count *= n;
  for (Index w = 0; w < count; ++w) {
    Vec<D> k;
    Index code = w;
    for (int a = 0; a < D; ++a) {
      k[a] = 2 * M_PI * static_cast<Real>(code % n) / n - M_PI;
      code /= n;
    }
    Eigen::Matrix<std::complex<Real>, D, D> symbol = Eigen::Matrix<std::complex<Real>, D, D>::Zero();
    for (int i = 0; i < D; ++i)
      for (SparseMatrix::InnerIterator it(K, static_cast<int>(D * centre + i)); it; ++it) {
        const Index b = it.row() / D;
        const int kk = static_cast<int>(it.row() % D);
        const Real phase = k.dot(particles.position(b) - particles.position(centre));
        symbol(i, kk) += it.value() * std::polar(1.0, phase) / mass;
      }
    const Eigen::VectorXd eig = hermitianEigenvalues(Eigen::MatrixXcd(symbol));
    smallest = std::min(smallest, eig.minCoeff());
    largest = std::max(largest, eig.maxCoeff());
  }
  EXPECT_GT(largest, 0);
  EXPECT_GE(smallest / largest, -1e-12) << D << "-D";
}

TEST(GalerkinLattice, InteriorSymbolIsNonNegativeOverTheWholeBrillouinZone) {
  checkInteriorSymbol<1>(256);
  checkInteriorSymbol<2>(64);
  checkInteriorSymbol<3>(24);
}

// Central difference on a free 3-D block from a random displacement: the discrete energy
// 1/2 v_{n-1/2}^T M v_{n+1/2} + 1/2 u_n^T K u_n is an exact invariant of the scheme when K is
// symmetric (it is what the ledger of a symmetric system closes on), so it holds to round-off over
// 10^4 steps at 0.9 of the stable step. With dashpots on every face it never rises.
Real energyDrift(bool dashpots, int steps, Real* finalFraction) {
  const ParticleSet<3> particles = block<3>(6, 0.5);
  VeryWeakSph<3> method = galerkin(particles);
  LinearSecondOrderSystem& system = method.system;
  if (dashpots) system.setDamping(lumpedFacetDashpots<3>(method.data.facets, kGalerkinMaterial, allFaces(3)));
  const StableTimeStep stable = centralDifferenceStableStep(system, 1e-8, 20000);
  const Real dt = 0.9 * stable.estimate();
  std::mt19937 rng(7);
  std::uniform_real_distribution<Real> uniform(-1, 1);
  Vector u0(system.size());
  for (Index i = 0; i < u0.size(); ++i) u0[i] = uniform(rng);
  CentralDifference integrator;
  integrator.initialise(system, 0, u0, Vector::Zero(system.size()), dt);
  const SparseMatrix& K = system.stiffness();
  const SparseMatrix& M = system.mass();
  Vector previousHalf = integrator.staggeredVelocity();
  Vector u = integrator.state().displacement;
  Real first = 0, largestChange = 0, largestRise = 0, last = 0;
  for (int s = 0; s < steps; ++s) {
    integrator.step();
    const Vector& half = integrator.staggeredVelocity();
    const Real energy = 0.5 * previousHalf.dot(M * half) + 0.5 * u.dot(K * u);  // E_n
    if (s == 0) first = energy;
    largestChange = std::max(largestChange, std::abs(energy - first));
    if (s > 0) largestRise = std::max(largestRise, energy - last);
    last = energy;
    previousHalf = half;
    u = integrator.state().displacement;
  }
  if (finalFraction) *finalFraction = last / first;
  return dashpots ? largestRise / first : largestChange / first;
}

TEST(GalerkinLattice, FreeBlockConservesTheCentralDifferenceEnergyOverTenThousandSteps) {
  EXPECT_LT(energyDrift(false, 10000, nullptr), 1e-8);
}

TEST(GalerkinLattice, DashpotsNeverRaiseTheEnergyAndRemoveAllButTheRigidPart) {
  Real fraction = 1;
  EXPECT_LE(energyDrift(true, 3000, &fraction), 1e-12);
  EXPECT_LT(fraction, 0.02);
}

// The inertia of K - tau M from a sparse LDL^T: the number of eigenvalues of M^-1 K below tau. On
// the 3-D Lamb block of the study at dx = 0.5 (3375 particles): none below -1e-9 omega^2_max, and
// exactly the six rigid-body modes below +1e-9 omega^2_max. With the dashpots (block-diagonal,
// positive semi-definite, checked block by block) no mode of M u'' + C u' + K u = 0 can grow.
TEST(GalerkinLattice, LambBlockOperatorHasNoNegativeModeAndDashpotsArePositive) {
  const ParticleSet<3> particles = makeBlock(Vec3(-3.5, -3.5, -7.0), Vec3(3.5, 3.5, 0.0), 0.5);
  VeryWeakSph<3> method = galerkin(particles, Material::fromLame(1, 1, 1));
  const SparseMatrix& K = method.system.stiffness();
  const SparseMatrix& M = method.system.mass();
  const Real omegaMax = std::pow(2 / centralDifferenceStableStep(method.system, 1e-6, 5000).estimate(), 2);
  auto below = [&](Real tau) {
    const SparseMatrix shifted = K - tau * M;
    Eigen::SimplicialLDLT<SparseMatrix> ldlt(shifted);
    EXPECT_EQ(ldlt.info(), Eigen::Success);
    return static_cast<int>((ldlt.vectorD().array() < 0).count());
  };
  EXPECT_EQ(below(-1e-9 * omegaMax), 0);
  EXPECT_EQ(below(1e-9 * omegaMax), 6);
  EXPECT_EQ(below(1e-3 * omegaMax), 6 + 0) << "lowest elastic mode of a 7 x 7 x 7 block is above 1e-3 omega_max";
  const std::uint8_t transmitting = static_cast<std::uint8_t>(allFaces(3) & ~faceBit(BoxFace::PlusZ));
  const SparseMatrix C = lumpedFacetDashpots<3>(method.data.facets, Material::fromLame(1, 1, 1), transmitting);
  EXPECT_EQ(SparseMatrix(C - SparseMatrix(C.transpose())).norm(), 0.0);
  const Eigen::MatrixXd c = Eigen::MatrixXd(C);
  for (Index a = 0; a < particles.physicalCount(); ++a) {
    const Eigen::Matrix3d blockAa = c.block<3, 3>(3 * a, 3 * a);
    EXPECT_GE(symmetricEigenvalues(blockAa).minCoeff(), 0.0);
  }
}

TEST(GalerkinLattice, PatchTentWeightsIntegrateTheRectangleExactly) {
  const ParticleSet<3> particles = makeBlock(Vec3(-3.5, -3.5, -7.0), Vec3(3.5, 3.5, 0.0), 0.25);
  const std::vector<Real> w = patchTentWeights<3>(particles, 5, Vec3(0.1, 0, 0), Vec3(0.5, 0.5, 0), 0.25,
                                                  Vec3(-3.5, -3.5, -7.0), Vec3(3.5, 3.5, 0.0));
  Real total = 0;
  for (const Real x : w) total += x * 0.25 * 0.25;
  EXPECT_NEAR(total, 1.0, 1e-13);
  // the same across a box edge: half the rectangle lies outside the face
  const std::vector<Real> edge = patchTentWeights<3>(particles, 5, Vec3(3.5, 0, 0), Vec3(0.5, 0.5, 0), 0.25,
                                                     Vec3(-3.5, -3.5, -7.0), Vec3(3.5, 3.5, 0.0));
  total = 0;
  for (const Real x : edge) total += x * 0.25 * 0.25;
  EXPECT_NEAR(total, 0.5, 1e-13);
}

TEST(GalerkinLattice, RefusesParticlesOffALattice) {
  ParticleSet<2> particles = makeRectangle(Vec2(0, 0), Vec2(1, 1), 0.25);
  particles.setPosition(3, particles.position(3) + Vec2(0.05, 0));
  EXPECT_THROW(galerkin(particles), InputError);
}

}  // namespace
}  // namespace mfwave
