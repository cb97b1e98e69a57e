// Collocation assembly (S d'' + A d = b), the constrained explicit form and the implicit Newmark:
// exactness on quadratic fields, which RK shape functions of order 2 reproduce with their
// derivatives, so every row must hold to round-off.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "CollocationTestSupport.hpp"
#include "analytic/StandingWave.hpp"
#include "core/Error.hpp"
#include "integrators/CentralDifference.hpp"
#include "integrators/ConstrainedNewmark.hpp"
#include "methods/collocation/CollocationSystem.hpp"
#include "methods/collocation/ConstrainedCollocationSystem.hpp"
#include "methods/collocation/ReproducingKernelShapeFunctions.hpp"

using namespace mfwave;
using mfwave::testing::nodePosition;
using mfwave::testing::unitLattice;

namespace {

// u_i(x) = c_i + g_i . x + 1/2 x^T H_i x with random coefficients (fixed seed).
template <int D>
struct QuadraticField {
  std::array<Real, D> c;
  std::array<Vec<D>, D> g;
  std::array<Mat<D>, D> h;

  explicit QuadraticField(unsigned seed, bool linear = false) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<Real> u(-1, 1);
    for (int i = 0; i < D; ++i) {
      c[i] = u(rng);
      for (int j = 0; j < D; ++j) g[i][j] = u(rng);
      Mat<D> m;
      for (int j = 0; j < D; ++j)
        for (int k = 0; k < D; ++k) m(j, k) = linear ? 0.0 : u(rng);
      h[i] = 0.5 * (m + m.transpose());
    }
  }
  Vec<D> value(const Vec<D>& x) const {
    Vec<D> v;
    for (int i = 0; i < D; ++i) v[i] = c[i] + g[i].dot(x) + 0.5 * x.dot(h[i] * x);
    return v;
  }
  Mat<D> gradient(const Vec<D>& x) const {  // (i, j) = du_i / dx_j
    Mat<D> m;
    for (int i = 0; i < D; ++i) m.row(i) = (g[i] + h[i] * x).transpose();
    return m;
  }
  // L u: 1-D E u'', else mu Lap u + (lambda + mu) grad div u (constant for a quadratic).
  Vec<D> operatorL(const Material& m) const {
    Vec<D> out;
    if constexpr (D == 1) {
      out[0] = m.youngsModulus() * h[0](0, 0);
    } else {
      for (int i = 0; i < D; ++i) {
        Real graddiv = 0;
        for (int j = 0; j < D; ++j) graddiv += h[j](i, j);
        out[i] = m.mu() * h[i].trace() + (m.lambda() + m.mu()) * graddiv;
      }
    }
    return out;
  }
  Vec<D> traction(const Material& m, const Vec<D>& x, const Vec<D>& n) const {
    const Mat<D> grad = gradient(x);
    if constexpr (D == 1) return Vec<D>::Constant(m.youngsModulus() * grad(0, 0) * n[0]);
    const Mat<D> sigma = m.lambda() * grad.trace() * Mat<D>::Identity() + m.mu() * (grad + grad.transpose());
    return sigma * n;
  }
};

template <int D>
Vector nodalValues(const Coordinates<D>& nodes, const QuadraticField<D>& f) {
  const Index n = static_cast<Index>(nodes[0].size());
  Vector d(n * D);
  for (Index J = 0; J < n; ++J) d.template segment<D>(J * D) = f.value(nodePosition<D>(nodes, J));
  return d;
}

template <int D>
void checkRowsReproduceTheField(int cells, Real perturbation, Real radiusOverH, const Material& material) {
  const Coordinates<D> nodes = unitLattice<D>(cells, perturbation);
  const ReproducingKernelShapeFunctions<D> rk(nodes, 2, radiusOverH / cells);
  const QuadraticField<D> field(42u + D);
  CollocationPoints<D> points;
  std::mt19937 rng(9);
  std::uniform_real_distribution<Real> u(0.05, 0.95);
  for (int p = 0; p < 12; ++p) {
    Vec<D> x;
    for (int a = 0; a < D; ++a) x[a] = u(rng);
    Vec<D> n;
    for (int a = 0; a < D; ++a) n[a] = u(rng) - 0.5;
    n.normalize();
    points.add(x, p % 3 == 0 ? CollocationRowKind::Interior
                             : p % 3 == 1 ? CollocationRowKind::Traction : CollocationRowKind::Displacement,
               n);
  }
  const CollocationSystem system = assembleCollocation<D>(rk, points, material);
  ASSERT_EQ(system.rows(), 12 * D);
  ASSERT_EQ(system.cols(), rk.nodeCount() * D);
  const Vector d = nodalValues<D>(nodes, field);
  const Vector ad = system.A * d, sd = system.S * d;
  for (std::size_t p = 0; p < points.size(); ++p) {
    const Vec<D>& x = points.points[p];
    Vec<D> expectedA = Vec<D>::Zero(), expectedS = Vec<D>::Zero();
    switch (points.kind[p]) {
      case CollocationRowKind::Interior:
        expectedA = -field.operatorL(material);
        expectedS = material.density() * field.value(x);
        break;
      case CollocationRowKind::Traction: expectedA = field.traction(material, x, points.normal[p]); break;
      case CollocationRowKind::Displacement: expectedA = field.value(x); break;
    }
    for (int i = 0; i < D; ++i) {
      const Index r = static_cast<Index>(p) * D + i;
      EXPECT_NEAR(ad[r], expectedA[i], 1e-9 * std::max<Real>(1, std::abs(expectedA[i]))) << "point " << p << " comp " << i;
      EXPECT_NEAR(sd[r], expectedS[i], 1e-9) << "point " << p;
      EXPECT_EQ(system.rowKind[static_cast<std::size_t>(r)], points.kind[p]);
    }
  }
}

}  // namespace

TEST(CollocationAssembly, OneDimensionalRowsAreExactForQuadratics) {
  checkRowsReproduceTheField<1>(20, 0.2, 3.3, Material::fromYoung(10, 0, 1.5));
}

TEST(CollocationAssembly, PlaneStrainRowsAreExactForQuadratics) {
  checkRowsReproduceTheField<2>(8, 0.2, 3.3, Material::fromLame(2.0, 3.0, 1.5));
}

TEST(CollocationAssembly, NavierRowsAreExactForQuadratics) {
  checkRowsReproduceTheField<3>(4, 0.1, 3.0, Material::fromLame(1.2, 0.7, 2.0));
}

TEST(CollocationAssembly, TractionRowsGiveSigmaNOfALinearField) {
  const Material material = Material::fromLame(2.0, 3.0, 1.0);
  const Coordinates<2> nodes = unitLattice<2>(6, 0.0);
  const ReproducingKernelShapeFunctions<2> rk(nodes, 1, 2.5 / 6);
  const QuadraticField<2> field(5u, true);
  CollocationPoints<2> points;
  points.add(Vec2(1.0, 0.4), CollocationRowKind::Traction, Vec2(1, 0));
  points.add(Vec2(0.3, 0.0), CollocationRowKind::Traction, Vec2(0, -1));
  const CollocationSystem system = assembleCollocation<2>(rk, points, material);
  const Vector ad = system.A * nodalValues<2>(nodes, field);
  // sigma n written out: sigma_xx = (lambda + 2 mu) u1,1 + lambda u2,2, sigma_xy = mu (u1,2 + u2,1)
  const Mat2 g = field.gradient(Vec2::Zero());
  const Real sxx = 8 * g(0, 0) + 2 * g(1, 1), syy = 2 * g(0, 0) + 8 * g(1, 1), sxy = 3 * (g(0, 1) + g(1, 0));
  EXPECT_NEAR(ad[0], sxx, 1e-10);
  EXPECT_NEAR(ad[1], sxy, 1e-10);
  EXPECT_NEAR(ad[2], -sxy, 1e-10);
  EXPECT_NEAR(ad[3], -syy, 1e-10);
}

TEST(CollocationAssembly, LoadsFillTheirRowsAndBadNormalsAreRejected) {
  const Coordinates<1> nodes = unitLattice<1>(10, 0.0);
  const ReproducingKernelShapeFunctions<1> rk(nodes, 2, 0.33);
  CollocationPoints<1> points;
  points.add(Vec1(0.0), CollocationRowKind::Displacement);
  points.add(Vec1(0.5), CollocationRowKind::Interior);
  points.add(Vec1(1.0), CollocationRowKind::Traction, Vec1(1.0));
  CollocationLoads<1> loads;
  loads.bodyForce = [](const Vec1& x, Real t) { return Vec1(x[0] + t); };
  loads.traction = [](const Vec1&, const Vec1& n, Real t) { return Vec1(2 * n[0] * t); };
  loads.displacement = [](const Vec1&, Real t) { return Vec1(-t); };
  const CollocationSystem system = assembleCollocation<1>(rk, points, Material::fromYoung(1, 0, 1), loads);
  const Vector b = system.rhs(3.0);
  EXPECT_DOUBLE_EQ(b[0], -3.0);
  EXPECT_DOUBLE_EQ(b[1], 3.5);
  EXPECT_DOUBLE_EQ(b[2], 6.0);
  points.normal[2] = Vec1(2.0);
  EXPECT_THROW(assembleCollocation<1>(rk, points, Material::fromYoung(1, 0, 1)), InputError);
}

namespace {

// Nodes = collocation points on [0, 1]^2 (n x n), displacement on -x and -y (corners included),
// traction on +x and +y.
CollocationPoints<2> squarePoints(const Coordinates<2>& nodes) {
  CollocationPoints<2> points;
  for (std::size_t i = 0; i < nodes[0].size(); ++i) {
    const Vec2 x(nodes[0][i], nodes[1][i]);
    const Real e = 1e-9;
    if (x[0] < e || x[1] < e) points.add(x, CollocationRowKind::Displacement);
    else if (x[0] > 1 - e) points.add(x, CollocationRowKind::Traction, Vec2(1, 0));
    else if (x[1] > 1 - e) points.add(x, CollocationRowKind::Traction, Vec2(0, 1));
    else points.add(x, CollocationRowKind::Interior);
  }
  return points;
}

}  // namespace

TEST(ConstrainedCollocation, OneDimensionalAccelerationIsExactForAConsistentQuadratic) {
  // u = x (2 - x): u(0) = 0, E u'(1) = 0, L u = -2 E: zero loads and zero boundary data.
  const Material material = Material::fromYoung(10, 0, 2.0);
  const Coordinates<1> nodes = unitLattice<1>(20, 0.0);
  const ReproducingKernelShapeFunctions<1> rk(nodes, 2, 3.3 / 20);
  CollocationPoints<1> points;
  for (Real x : nodes[0])
    points.add(Vec1(x), x == 0 ? CollocationRowKind::Displacement
                               : x == 1 ? CollocationRowKind::Traction : CollocationRowKind::Interior,
               Vec1(1.0));
  ConstrainedCollocationSystem system(assembleCollocation<1>(rk, points, material));
  ASSERT_EQ(system.size(), 19);
  EXPECT_FALSE(system.isLeastSquares());
  Vector U(19), a(19);
  for (Index r = 0; r < 19; ++r) {
    const Real x = nodes[0][static_cast<std::size_t>(system.interiorRows()[static_cast<std::size_t>(r)])];
    U[r] = x * (2 - x);
  }
  system.acceleration(0, U, U, a);
  for (Index r = 0; r < 19; ++r) EXPECT_NEAR(a[r], -2 * 10 / 2.0, 1e-9) << r;
  // The coefficients reproduce u at any point, boundary included.
  const Vector d = system.coefficients(U, 0);
  const Vector u = evaluateCollocationField<1>(rk, d, {Vec1(0.0), Vec1(0.37), Vec1(1.0)});
  EXPECT_NEAR(u[0], 0, 1e-12);
  EXPECT_NEAR(u[1], 0.37 * 1.63, 1e-12);
  EXPECT_NEAR(u[2], 1, 1e-12);
  // K U = -a(U) for any U, zero loads.
  const Eigen::MatrixXd K = system.denseStiffness();
  ASSERT_EQ(K.rows(), 19);
  const Vector W = Vector::LinSpaced(19, -1, 2).array().sin();
  Vector aw(19);
  system.acceleration(0, W, W, aw);
  EXPECT_LT((K * W + aw).norm(), 1e-10 * aw.norm());
  EXPECT_LT((K * U + a).norm(), 1e-10 * a.norm());
}

TEST(ConstrainedCollocation, PlaneStrainAccelerationIsExactWithBodyForceAndBoundaryData) {
  const Material material = Material::fromLame(2.0, 3.0, 1.5);
  const Coordinates<2> nodes = unitLattice<2>(8, 0.0);
  const ReproducingKernelShapeFunctions<2> rk(nodes, 2, 3.3 / 8);
  const CollocationPoints<2> points = squarePoints(nodes);
  const QuadraticField<2> field(7u);
  const Vec2 f(0.3, -0.8);
  CollocationLoads<2> loads;
  loads.bodyForce = [&](const Vec2&, Real) { return f; };
  loads.traction = [&](const Vec2& x, const Vec2& n, Real) { return field.traction(material, x, n); };
  loads.displacement = [&](const Vec2& x, Real) { return field.value(x); };
  ConstrainedCollocationSystem system(assembleCollocation<2>(rk, points, material, loads));
  Vector U(system.size()), a(system.size());
  for (Index r = 0; r < system.size(); r += 2) {
    const Index p = system.interiorRows()[static_cast<std::size_t>(r)] / 2;
    U.segment<2>(r) = field.value(points.points[static_cast<std::size_t>(p)]);
  }
  system.acceleration(0, U, U, a);
  const Vec2 expected = (field.operatorL(material) + f) / material.density();
  for (Index r = 0; r < system.size(); r += 2) {
    EXPECT_NEAR(a[r], expected[0], 1e-9);
    EXPECT_NEAR(a[r + 1], expected[1], 1e-9);
  }
}

TEST(ConstrainedCollocation, TheAdjointCarriesAFunctionalOfTheCoefficientsToTheRightHandSide) {
  // A fixed-free bar with a traction history h(t) = t^2 at x = 1: a probe of u^h (or of its rate)
  // through g = C^{-T} r must equal r . d (r . d') from the solves, and b_B'(t) = 2 t.
  const Material material = Material::fromYoung(3, 0, 1.0);
  const Coordinates<1> nodes = unitLattice<1>(16, 0.0);
  const ReproducingKernelShapeFunctions<1> rk(nodes, 2, 3.3 / 16);
  CollocationLoads<1> loads;
  loads.traction = [](const Vec1&, const Vec1&, Real t) { return Vec1(t * t); };
  ConstrainedCollocationSystem system(assembleCollocation<1>(rk, fixedFreeBarPoints(nodes), material, loads));
  const Real t = 0.7;
  const Vector rate = system.boundaryDataRate(t, 1);
  ASSERT_EQ(rate.size(), 2);  // the displacement row at 0, the traction row at 1
  EXPECT_NEAR(rate[0], 0, 1e-12);
  EXPECT_NEAR(rate[1], 2 * t, 1e-7);
  EXPECT_NEAR(system.boundaryDataRate(t, 2)[1], 2, 1e-4);
  // r: u^h at x = 0.83 and at the free end.
  Eigen::MatrixXd r = Eigen::MatrixXd::Zero(system.system().cols(), 2);
  ShapeFunctionValues<1> values;
  const std::array<Real, 2> at{0.83, 1.0};
  for (Index c = 0; c < 2; ++c) {
    rk.evaluate(Vec1(at[static_cast<std::size_t>(c)]), 0, values);
    for (Index k = 0; k < values.size(); ++k)
      r(values.nodes[static_cast<std::size_t>(k)], c) = values.value[static_cast<std::size_t>(k)];
  }
  const Eigen::MatrixXd g = system.constraintAdjoint(r);
  ASSERT_EQ(g.rows(), system.size() + 2);
  const Vector U = Vector::LinSpaced(system.size(), 0.1, 0.9).array().sin();
  const Vector V = Vector::LinSpaced(system.size(), -1, 1).array().cos();
  Vector top(system.size() + 2), topRate(system.size() + 2);
  top << U, system.boundaryData(t);
  topRate << V, rate;
  const Vector d = system.coefficients(U, t), dRate = system.coefficientRates(V, t);
  for (Index c = 0; c < 2; ++c) {
    EXPECT_NEAR(g.col(c).dot(top), r.col(c).dot(d), 1e-10 * (1 + std::abs(r.col(c).dot(d))));
    EXPECT_NEAR(g.col(c).dot(topRate), r.col(c).dot(dRate), 1e-10 * (1 + std::abs(r.col(c).dot(dRate))));
  }
  EXPECT_THROW(system.constraintAdjoint(Eigen::MatrixXd::Zero(3, 1)), InputError);
}

TEST(ConstrainedCollocation, LeastSquaresWithMorePointsThanNodesIsExactForQuadratics) {
  const Material material = Material::fromYoung(4, 0, 1.0);
  const Coordinates<1> nodes = unitLattice<1>(10, 0.0);
  const ReproducingKernelShapeFunctions<1> rk(nodes, 2, 3.3 / 10);
  CollocationPoints<1> points;
  points.add(Vec1(0.0), CollocationRowKind::Displacement);
  for (int i = 1; i < 20; ++i) points.add(Vec1(i / 20.0), CollocationRowKind::Interior);
  points.add(Vec1(1.0), CollocationRowKind::Traction, Vec1(1.0));
  ConstrainedCollocationSystem system(assembleCollocation<1>(rk, points, material));
  EXPECT_TRUE(system.isLeastSquares());
  Vector U(19), a(19);
  for (Index r = 0; r < 19; ++r) U[r] = (r + 1) / 20.0 * (2 - (r + 1) / 20.0);
  system.acceleration(0, U, U, a);
  for (Index r = 0; r < 19; ++r) EXPECT_NEAR(a[r], -2 * 4.0, 1e-8);
}

TEST(ConstrainedCollocation, RejectsFewerPointsThanNodes) {
  const Coordinates<1> nodes = unitLattice<1>(10, 0.0);
  const ReproducingKernelShapeFunctions<1> rk(nodes, 2, 0.33);
  CollocationPoints<1> points;
  points.add(Vec1(0.0), CollocationRowKind::Displacement);
  points.add(Vec1(0.5), CollocationRowKind::Interior);
  EXPECT_THROW(ConstrainedCollocationSystem(assembleCollocation<1>(rk, points, Material::fromYoung(1, 0, 1))),
               InputError);
}

namespace {

// Standing wave sin(pi x) cos(pi c t) in a fixed-fixed bar, 41 nodes, RK m = 2; error at T = 1.3.
Real standingWaveError(SecondOrderIntegrator& integrator, Real dt) {
  const Material material = Material::fromYoung(1, 0, 1);
  const Coordinates<1> nodes = unitLattice<1>(40, 0.0);
  const ReproducingKernelShapeFunctions<1> rk(nodes, 2, 3.3 / 40);
  CollocationPoints<1> points;
  for (Real x : nodes[0])
    points.add(Vec1(x), x == 0 || x == 1 ? CollocationRowKind::Displacement : CollocationRowKind::Interior);
  ConstrainedCollocationSystem system(assembleCollocation<1>(rk, points, material));
  const StandingWave exact(1, 1.0, 1.0);
  Vector U(system.size()), V = Vector::Zero(system.size());
  for (Index r = 0; r < U.size(); ++r) U[r] = exact.displacement(nodes[0][static_cast<std::size_t>(r + 1)], 0);
  integrator.initialise(system, 0, U, V, dt);
  integrator.advanceTo(1.3);
  Real e = 0;
  for (Index r = 0; r < U.size(); ++r)
    e = std::max(e, std::abs(integrator.state().displacement[r] -
                             exact.displacement(nodes[0][static_cast<std::size_t>(r + 1)], 1.3)));
  return e;
}

}  // namespace

TEST(CollocationTimeIntegration, CentralDifferenceAndImplicitNewmarkFollowAStandingWave) {
  CentralDifference explicitScheme;
  ConstrainedNewmark implicitScheme(0.25, 0.5);
  const Real eExplicit = standingWaveError(explicitScheme, 0.01);
  const Real eImplicit = standingWaveError(implicitScheme, 0.01);
  // Measured 2.0e-3 and 1.6e-3: the O(h^2) space error of m = 2 collocation dominates.
  EXPECT_LT(eExplicit, 3e-3);
  EXPECT_LT(eImplicit, 3e-3);
  EXPECT_GT(eExplicit, 1e-4);  // not trivially zero
  // The implicit scheme is unconditionally stable: a step 4 times the spacing still runs.
  ConstrainedNewmark large(0.25, 0.5);
  const Real eLarge = standingWaveError(large, 0.1);
  EXPECT_TRUE(std::isfinite(eLarge));
  EXPECT_LT(eLarge, 0.1);
  EXPECT_THROW(ConstrainedNewmark(0.0, 0.5), InputError);
}
