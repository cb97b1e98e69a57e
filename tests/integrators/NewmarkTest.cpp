// Newmark: energy conservation, unconditional stability, parameter and system checks, UMFPACK path.

#include "TestSystems.hpp"
#include "core/Error.hpp"
#include "integrators/Leapfrog.hpp"
#include "integrators/Newmark.hpp"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <cmath>

using namespace mfwave;

namespace {

TEST(Newmark, AverageAccelerationConservesEnergyOverManySteps) {
  const Real w = 3.0;
  auto system = test::oscillator(w, 0);
  Newmark newmark(0.25, 0.5);
  Vector u0(1), v0(1);
  u0 << 1;
  v0 << 0.5;
  newmark.initialise(*system, 0, u0, v0, 0.1 / w);
  EXPECT_TRUE(newmark.effectiveMatrixIsDiagonal());
  const Real e0 = system->kineticEnergy(v0) + system->strainEnergy(u0);
  Real maxError = 0;
  for (int i = 0; i < 100000; ++i) {
    newmark.step();
    const auto s = newmark.state();
    maxError = std::max(maxError, std::abs(system->kineticEnergy(s.velocity) + system->strainEnergy(s.displacement) - e0) / e0);
  }
  std::printf("Newmark average acceleration: max relative energy error %.3e over 1e5 steps\n", maxError);
  EXPECT_LT(maxError, 1e-12);
}

TEST(Newmark, AverageAccelerationIsStableFarBeyondTheExplicitLimitOnAChain) {
  // 50-dof chain, highest frequency ~2: explicit limit dt ~ 1. dt = 10 is ten times beyond it, and the
  // effective matrix M + dt^2/4 K is tridiagonal, so this goes through UMFPACK.
  const int n = 50;
  auto system = test::springChain(n);
  const Vector u0 = test::chainInitialDisplacement(n);
  const Vector v0 = Vector::Zero(n);
  const Real dt = 10.0;
  Newmark newmark(0.25, 0.5);
  newmark.initialise(*system, 0, u0, v0, dt);
  EXPECT_FALSE(newmark.effectiveMatrixIsDiagonal());
  const Real e0 = system->strainEnergy(u0);
  // Energy bound: u^T K u <= 2 E0, so |u|_2 <= sqrt(2 E0 / lambda_min(K)).
  const Real lambdaMin = 2 - 2 * std::cos(M_PI / (n + 1));
  const Real bound = std::sqrt(2 * e0 / lambdaMin);
  Real maxNorm = 0, maxEnergyError = 0;
  for (int i = 0; i < 400; ++i) {
    newmark.step();
    const auto s = newmark.state();
    maxNorm = std::max(maxNorm, s.displacement.norm());
    maxEnergyError = std::max(maxEnergyError,
                              std::abs(system->kineticEnergy(s.velocity) + system->strainEnergy(s.displacement) - e0) / e0);
  }
  EXPECT_LE(maxNorm, bound);
  EXPECT_LT(maxEnergyError, 1e-11);

  // The same step really is beyond the explicit limit: leapfrog explodes.
  Leapfrog leapfrog;
  leapfrog.initialise(*system, 0, u0, v0, dt);
  for (int i = 0; i < 20; ++i) leapfrog.step();
  EXPECT_GT(leapfrog.state().displacement.norm(), 1e3 * bound);
}

TEST(Newmark, InitialAccelerationSolvesTheConsistentMassSystem) {
  // Consistent (non-diagonal) mass: a_0 = M^{-1} (f(t0) - C v0 - K u0), through UMFPACK.
  SparseMatrix m(2, 2), c(2, 2), k(2, 2);
  m.insert(0, 0) = 2;
  m.insert(0, 1) = 1;
  m.insert(1, 0) = 1;
  m.insert(1, 1) = 3;
  c.insert(0, 0) = 0.5;
  k.insert(0, 0) = 4;
  k.insert(0, 1) = -1;
  k.insert(1, 0) = -1;
  k.insert(1, 1) = 5;
  LinearSecondOrderSystem system(m, c, k, [](Real t, Vector& f) {
    f[0] = 1 + t;
    f[1] = -2;
  });
  Vector u0(2), v0(2);
  u0 << 0.3, -0.2;
  v0 << 1, 2;
  Newmark newmark;
  newmark.initialise(system, 0.5, u0, v0, 0.01);
  Vector f(2);
  f << 1.5, -2;
  const Vector expected = Eigen::MatrixXd(m).lu().solve(f - Eigen::MatrixXd(c) * v0 - Eigen::MatrixXd(k) * u0);
  EXPECT_NEAR((newmark.acceleration() - expected).norm(), 0, 1e-14);

  // One step against the formulas written out densely (eqs. 27-31).
  newmark.step();
  const Real dt = 0.01, beta = 0.25, gamma = 0.5;
  const Vector uT = u0 + dt * v0 + dt * dt * (0.5 - beta) * expected;
  const Vector vT = v0 + dt * (1 - gamma) * expected;
  Vector f1(2);
  f1 << 1.51, -2;
  const Eigen::MatrixXd s = Eigen::MatrixXd(m) + gamma * dt * Eigen::MatrixXd(c) + beta * dt * dt * Eigen::MatrixXd(k);
  const Vector a1 = s.lu().solve(f1 - Eigen::MatrixXd(c) * vT - Eigen::MatrixXd(k) * uT);
  EXPECT_NEAR((newmark.state().displacement - (uT + beta * dt * dt * a1)).norm(), 0, 1e-14);
  EXPECT_NEAR((newmark.state().velocity - (vT + gamma * dt * a1)).norm(), 0, 1e-14);
}

TEST(Newmark, ParametersOutOfRangeNameTheirKey) {
  try {
    Newmark bad(0.6, 0.5);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "newmark.beta");
  }
  try {
    Newmark bad(0.25, 1.2);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "newmark.gamma");
  }
  EXPECT_NO_THROW(Newmark(0, 0.5));
  EXPECT_NO_THROW(Newmark(0.5, 0.3));
}

TEST(Newmark, NeedsALinearSystem) {
  struct Pendulum : SecondOrderSystem {
    Index size() const override { return 1; }
    void acceleration(Real, Eigen::Ref<const Vector> u, Eigen::Ref<const Vector>, Eigen::Ref<Vector> a) override { a = -u.array().sin().matrix(); }
  } pendulum;
  Newmark newmark;
  try {
    newmark.initialise(pendulum, 0, Vector::Ones(1), Vector::Zero(1), 0.1);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "integrator");
    EXPECT_NE(std::string(e.what()).find("linear system"), std::string::npos);
  }
}

TEST(Newmark, SingularEffectiveMatrixIsAClearError) {
  // Diagonal path: 1 + beta dt^2 k = 0 for k = -4, beta = 1/4, dt = 1.
  LinearSecondOrderSystem diagonal(test::scalarMatrix(1), SparseMatrix(), test::scalarMatrix(-4));
  Newmark newmark(0.25, 0.5);
  try {
    newmark.initialise(diagonal, 0, Vector::Ones(1), Vector::Zero(1), 1.0);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("effective matrix"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("singular"), std::string::npos) << e.what();
  }
  // UMFPACK path: I + K/4 with K = -2 [[1, 1], [1, 1]] is singular and not diagonal.
  SparseMatrix k(2, 2), m(2, 2);
  m.setIdentity();
  k.insert(0, 0) = -2;
  k.insert(0, 1) = -2;
  k.insert(1, 0) = -2;
  k.insert(1, 1) = -2;
  LinearSecondOrderSystem coupled(m, SparseMatrix(), k);
  try {
    newmark.initialise(coupled, 0, Vector::Ones(2), Vector::Zero(2), 1.0);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("effective matrix"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("singular"), std::string::npos) << e.what();
  }
  // A singular mass matrix is reported as such.
  LinearSecondOrderSystem massless(test::scalarMatrix(0), SparseMatrix(), test::scalarMatrix(1));
  try {
    newmark.initialise(massless, 0, Vector::Ones(1), Vector::Zero(1), 1.0);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("mass matrix"), std::string::npos) << e.what();
  }
}

}  // namespace
