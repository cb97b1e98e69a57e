// Patch tests of the consistent variant (ConsistentCorrection.hpp) against the published operator:
// for every displacement field u = e_k m(x), m a monomial of degree <= 2 (translation, uniform
// strain, quadratic), with the tractions sigma(u) n on every facet, the right-hand side rho u''_a
// must equal div sigma(u)(x^a) at every particle. lambda = 2, mu = 1, so that the lambda and mu
// terms are told apart. Lattices in 1-D, 2-D and 3-D, regular and with the interior particles moved
// randomly (face particles only within their faces), h = dx, two ghost layers.

#include "core/Error.hpp"
#include "core/Material.hpp"
#include "kernels/CubicSplineKernel.hpp"
#include "methods/very_weak_sph/QuadraticMonomials.hpp"
#include "methods/very_weak_sph/TractionLoad.hpp"
#include "methods/very_weak_sph/TransmittingBoundary.hpp"
#include "methods/very_weak_sph/VeryWeakSph.hpp"
#include "neighbours/NeighbourList.hpp"
#include "particles/BoxFace.hpp"
#include "particles/GhostLayers.hpp"
#include "particles/Lattice.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>

using namespace mfwave;

namespace {

template <int D>
struct Cloud {
  ParticleSet<D> particles;
  NeighbourList neighbours;
  CubicSplineKernel kernel;
  Vec<D> centre;
  Real halfWidth;
};

// The lattice [0, cells dx]^D with h = dx and two ghost layers; every coordinate not fixed by a face
// moved by up to `jitter` dx (uniform, from a fixed seed, reproducible on every standard library).
template <int D>
Cloud<D> makeCloud(int cells, Real dx, Real jitter, unsigned seed) {
  const Vec<D> lower = Vec<D>::Zero(), upper = Vec<D>::Constant(cells * dx);
  Cloud<D> cloud{makeLattice<D>(lower, upper, dx), NeighbourList(), CubicSplineKernel(D, dx), 0.5 * upper,
                 0.5 * cells * dx};
  std::mt19937 random(seed);
  for (Index a = 0; a < cloud.particles.physicalCount(); ++a) {
    Vec<D> x = cloud.particles.position(a);
    const std::uint8_t mask = cloud.particles.faceMask[static_cast<std::size_t>(a)];
    for (int j = 0; j < D; ++j) {
      const Real unit = 2.0 * static_cast<Real>(random()) / 4294967295.0 - 1.0;  // in [-1, 1]
      if ((mask & (faceBit(2 * j) | faceBit(2 * j + 1))) == 0) x[j] += jitter * dx * unit;
    }
    cloud.particles.setPosition(a, x);
  }
  addGhostLayers<D>(cloud.particles, lower, upper, dx, 2, allFaces(D));
  cloud.neighbours = buildNeighbourList(CellList<D>(cloud.particles, cloud.kernel.supportRadius()),
                                        cloud.particles.physicalCount());
  return cloud;
}

// Particle classes: interior (no facet in its row), near the boundary (facets in its row but none
// of its own), then by the number of its own facets: face, edge, corner (1-D: the ends are corners).
enum Kind { Interior, Near, Face, Edge, Corner, KindCount };
const char* const kindName[] = {"interior", "near", "face", "edge", "corner"};
enum FieldClass { Constant, Linear, Quadratic, ClassCount };
const char* const className[] = {"constant", "linear", "quadratic"};

using Table = std::array<std::array<Real, ClassCount>, KindCount>;  // max relative residual; -1 if no particle

template <int D>
Kind kindOf(const Cloud<D>& cloud, const SparseMatrix& traction, Index a) {
  const int m = cloud.particles.facetCount(a);
  if (m == D) return Corner;
  if (m == 2) return Edge;
  if (m == 1) return Face;
  const Eigen::SparseMatrix<Real, Eigen::RowMajor, int> rows(traction.middleRows(D * a, 1));
  return rows.nonZeros() > 0 ? Near : Interior;
}

// For each field u = e_k m((x - c) / L) with its facet tractions, the residual of
// rho u''_a = rowFactor_a (K u + T t)_a against div sigma(x^a), relative to the sum of the absolute
// values of the terms: |r| / (rowFactor_a (|K| |u| + |T| |t|)_a + |div sigma|).
template <int D>
Table patchResiduals(const Cloud<D>& cloud, const VeryWeakSph<D>& vw, const Material& material) {
  const Index n = cloud.particles.physicalCount();
  const Real lambda = material.lambda(), mu = material.mu(), length = cloud.halfWidth;
  const SparseMatrix& k = vw.data.operatorMatrix;
  const SparseMatrix& t = vw.data.tractionMatrix;
  const SparseMatrix absK = k.cwiseAbs(), absT = t.cwiseAbs();
  const QuadraticMonomials<D> monomials;
  Table table;
  for (auto& row : table) row.fill(-1);
  for (int m = 0; m < QuadraticMonomials<D>::count; ++m) {
    const FieldClass fieldClass = m == 0 ? Constant : (m <= D ? Linear : Quadratic);
    for (int c = 0; c < D; ++c) {
      Vector u = Vector::Zero(D * n);
      for (Index b = 0; b < n; ++b)
        u[D * b + c] = monomials.value(m, Vec<D>((cloud.particles.position(b) - cloud.centre) / length));
      Vector traction(D * vw.data.facets.count());
      for (Index f = 0; f < vw.data.facets.count(); ++f) {
        const auto fi = static_cast<std::size_t>(f);
        const Vec<D> x = cloud.particles.position(vw.data.facets.particle[fi]);
        const Vec<D> g = monomials.gradient(m, Vec<D>((x - cloud.centre) / length)) / length;
        // sigma_lj = lambda delta_lj d_c m + mu (delta_lc d_j m + delta_jc d_l m)
        Mat<D> strainGradient = Mat<D>::Zero();
        strainGradient.row(c) = g.transpose();  // grad u, (grad u)_lj = d_j u_l
        const Mat<D> sigma = lambda * strainGradient.trace() * Mat<D>::Identity() +
                             mu * (strainGradient + strainGradient.transpose());
        traction.template segment<D>(D * f) = sigma * vw.data.facets.normal[fi];
      }
      const Vector rhs = k * u + t * traction;
      const Vector scale = absK * u.cwiseAbs() + absT * traction.cwiseAbs();
      const Mat<D> hess = monomials.hessian(m) / (length * length);
      for (Index a = 0; a < n; ++a) {
        const Real factor = vw.data.alpha[static_cast<std::size_t>(a)];
        const int kind = kindOf(cloud, t, a);
        for (int i = 0; i < D; ++i) {
          const Real target = (lambda + mu) * hess(i, c) + (i == c ? mu * hess.trace() : 0.0);
          const Real residual = std::abs(factor * rhs[D * a + i] - target) / (factor * scale[D * a + i] + std::abs(target));
          Real& entry = table[static_cast<std::size_t>(kind)][fieldClass];
          entry = std::max(entry, residual);
        }
      }
    }
  }
  return table;
}

void print(const char* title, const Table& published, const Table& consistent) {
  std::printf("%s: max relative residual, published | consistent\n", title);
  for (int kind = 0; kind < KindCount; ++kind) {
    if (published[static_cast<std::size_t>(kind)][0] < 0) continue;
    std::printf("  %-8s", kindName[kind]);
    for (int c = 0; c < ClassCount; ++c)
      std::printf("  %s %.3e | %.1e", className[c], published[static_cast<std::size_t>(kind)][static_cast<std::size_t>(c)],
                  consistent[static_cast<std::size_t>(kind)][static_cast<std::size_t>(c)]);
    std::printf("\n");
  }
}

template <int D>
std::array<Table, 2> measure(const char* title, const Cloud<D>& cloud) {
  VeryWeakSphOptions options;
  options.material = Material::fromLame(2, 1, 1);
  const VeryWeakSph<D> published = assembleVeryWeakSph(cloud.particles, cloud.neighbours, cloud.kernel, options);
  options.variant = VeryWeakSphVariant::Consistent;
  const VeryWeakSph<D> consistent = assembleVeryWeakSph(cloud.particles, cloud.neighbours, cloud.kernel, options);
  const Table p = patchResiduals(cloud, published, options.material);
  const Table c = patchResiduals(cloud, consistent, options.material);
  print(title, p, c);
  std::printf("  correction: %lld particle rows, max residual %.3e\n",
              static_cast<long long>(consistent.data.consistentRowsSolved), consistent.data.consistencyResidual);
  EXPECT_EQ(consistent.data.consistentRowsSolved, cloud.particles.physicalCount());
  EXPECT_LT(consistent.data.consistencyResidual, 1e-10);
  for (const auto& row : c)
    for (Real value : row) EXPECT_LT(value, 1e-10);
  return {p, c};
}

// The published operator's largest residual per particle kind (over the three field classes),
// asserted as measured (to 1e-6 relative); -1 for a kind the cloud does not have.
void expectPublished(const Table& measured, const std::array<Real, KindCount>& expected) {
  std::array<Real, KindCount> worst{};
  for (std::size_t kind = 0; kind < KindCount; ++kind)
    worst[kind] = *std::max_element(measured[kind].begin(), measured[kind].end());
  std::printf("  published, worst per kind: {%.17g, %.17g, %.17g, %.17g, %.17g}\n", worst[0], worst[1], worst[2],
              worst[3], worst[4]);
  for (std::size_t kind = 0; kind < KindCount; ++kind) {
    if (expected[kind] < 0)
      EXPECT_EQ(worst[kind], -1.0) << kindName[kind];
    else if (expected[kind] == 0)
      EXPECT_LT(worst[kind], 1e-15) << kindName[kind];  // exact: the 1-D cubic B-spline's own moments
    else
      EXPECT_NEAR(worst[kind], expected[kind], 1e-6 * expected[kind]) << kindName[kind];
  }
}

}  // namespace

TEST(ConsistentVariant, PatchTestsOneDimension) {
  expectPublished(measure("1-D regular, 9 particles", makeCloud<1>(8, 0.5, 0.0, 1))[0],
                  {0, 0.036437246963562674, -1, -1, 0.085106382978723458});
  expectPublished(measure("1-D perturbed", makeCloud<1>(8, 0.5, 0.2, 7))[0],
                  {0.45836820331027983, 0.13617410863980051, -1, -1, 0.15374691134283783});
}

TEST(ConsistentVariant, PatchTestsTwoDimensions) {
  expectPublished(measure("2-D regular, 7 x 7", makeCloud<2>(6, 0.5, 0.0, 1))[0],
                  {0.03027548816160398, 0.089932160553893109, 0.17199089561046799, -1, 0.17199089561046793});
  expectPublished(measure("2-D perturbed", makeCloud<2>(6, 0.5, 0.2, 11))[0],
                  {0.40856306351557042, 0.54866005592015721, 0.4744907974766055, -1, 0.50765492598861039});
}

TEST(ConsistentVariant, PatchTestsThreeDimensions) {
  expectPublished(measure("3-D regular, 6 x 6 x 6", makeCloud<3>(5, 0.5, 0.0, 1))[0],
                  {0.026379340385629883, 0.11700426882299417, 0.17067579135348951, 0.17067579135348951,
                   0.16242361797387686});
  expectPublished(measure("3-D perturbed", makeCloud<3>(5, 0.5, 0.2, 13))[0],
                  {0.23168867701484749, 0.49165234449709994, 0.57134187804406944, 0.58883848120116788,
                   0.58864165666234747});
}

TEST(ConsistentVariant, NodalSystemWithMassRhoAndDashpotsThroughTheTractionMatrix) {
  const Cloud<3> cloud = makeCloud<3>(3, 0.5, 0.0, 1);
  const Index n = cloud.particles.physicalCount();
  VeryWeakSphOptions options;
  options.material = Material::fromLame(2, 1, 2.5);
  const VeryWeakSph<3> published = assembleVeryWeakSph(cloud.particles, cloud.neighbours, cloud.kernel, options);
  options.variant = VeryWeakSphVariant::Consistent;
  const VeryWeakSph<3> vw = assembleVeryWeakSph(cloud.particles, cloud.neighbours, cloud.kernel, options);
  for (Real alpha : vw.data.alpha) EXPECT_EQ(alpha, 1.0);
  EXPECT_LT((Eigen::MatrixXd(vw.system.mass()) - 2.5 * Eigen::MatrixXd::Identity(3 * n, 3 * n)).norm(), 1e-14);
  EXPECT_LT((Eigen::MatrixXd(vw.system.stiffness()) + Eigen::MatrixXd(vw.data.operatorMatrix)).norm(), 1e-14);
  EXPECT_EQ(published.data.consistentRowsSolved, 0);
  // The corrected traction blocks are full D x D (the published ones W A I).
  EXPECT_EQ(vw.data.tractionMatrix.nonZeros(), 3 * published.data.tractionMatrix.nonZeros());

  const std::uint8_t mask = faceBit(BoxFace::MinusZ) | faceBit(BoxFace::PlusX);
  // With the published T, C = T Z P is the traction-sum lumping of assembleTransmittingDamping.
  const SparseMatrix viaT = dashpotsThroughTractionMatrix(published.data.tractionMatrix, published.data.facets,
                                                          options.material, mask);
  const SparseMatrix direct = assembleTransmittingDamping(cloud.particles, cloud.neighbours, cloud.kernel,
                                                          published.data.facets, options.material, mask,
                                                          DashpotLumping::Consistent);
  EXPECT_LT((Eigen::MatrixXd(viaT) - Eigen::MatrixXd(direct)).norm(), 1e-12 * Eigen::MatrixXd(direct).norm());
  // With the corrected T: -C v = T t with t_f = -rho Z_f v_particle(f) on the transmitting facets.
  const SparseMatrix c = dashpotsThroughTractionMatrix(vw.data.tractionMatrix, vw.data.facets, options.material, mask);
  Vector v(3 * n);
  for (Index a = 0; a < n; ++a) v.segment<3>(3 * a) = Vec3(0.3, -0.2, 1.0) + 0.1 * cloud.particles.position(a);
  Vector t = Vector::Zero(3 * vw.data.facets.count());
  for (Index f = 0; f < vw.data.facets.count(); ++f) {
    const auto fi = static_cast<std::size_t>(f);
    if ((mask & faceBit(vw.data.facets.face[fi])) == 0) continue;
    t.segment<3>(3 * f) = -2.5 * dashpotImpedance<3>(options.material, vw.data.facets.normal[fi]) *
                          v.segment<3>(3 * vw.data.facets.particle[fi]);
  }
  const Vector force = vw.data.tractionMatrix * t;
  EXPECT_LT((c * v + force).norm(), 1e-12 * force.norm());
  EXPECT_THROW(dashpotsThroughTractionMatrix(vw.data.tractionMatrix, vw.data.facets, options.material, 0x40), InputError);
}

TEST(ConsistentVariant, ThrowsNamingTheParticleWhoseRowCannotBeMet) {
  // h = dx / 2: the support radius is dx, so every row holds only the particle itself.
  ParticleSet<3> particles = makeLattice<3>(Vec3::Zero(), Vec3::Constant(2), 1.0);
  const CubicSplineKernel kernel(3, 0.5);
  const NeighbourList neighbours = buildNeighbourList(CellList<3>(particles, kernel.supportRadius()), particles.physicalCount());
  VeryWeakSphOptions options;
  options.variant = VeryWeakSphVariant::Consistent;
  try {
    assembleVeryWeakSph(particles, neighbours, kernel, options);
    ADD_FAILURE() << "expected an Error";
  } catch (const Error& error) {
    std::printf("%s\n", error.what());
    EXPECT_NE(std::string(error.what()).find("particle 0 at (0 0 0)"), std::string::npos);
  }
}
