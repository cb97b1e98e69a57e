// Central difference with implicit dashpots (Ding-Long-Wu eq. 32) against the exact solutions of
// damped oscillators, its stability where the explicit predictor fails, and its identity with the
// classical scheme when there is no damping.

#include "TestSystems.hpp"
#include "core/Error.hpp"
#include "integrators/CentralDifference.hpp"
#include "integrators/IntegratorFactory.hpp"
#include "solvers/DenseEigenproblems.hpp"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <vector>

using namespace mfwave;

namespace {

using DashpotOperator = CentralDifference::Damping;

// M u'' + C u' + K u = 0 from (u0, v0), exactly: y = [u; v] solves y' = A y with
// A = [0 I; -M^-1 K  -M^-1 C], and y(t) = V exp(Lambda t) V^-1 y0 from A's eigen-decomposition.
class ExactLinearMotion {
 public:
  ExactLinearMotion(const Eigen::MatrixXd& m, const Eigen::MatrixXd& c, const Eigen::MatrixXd& k, const Vector& u0,
                    const Vector& v0)
      : n_(m.rows()) {
    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(2 * n_, 2 * n_);
    a.topRightCorner(n_, n_).setIdentity();
    a.bottomLeftCorner(n_, n_) = -m.inverse() * k;
    a.bottomRightCorner(n_, n_) = -m.inverse() * c;
    GeneralEigenpairs eigen = generalEigenpairs(a, true);
    vectors_ = std::move(eigen.vectors);
    values_ = std::move(eigen.values);
    Vector y0(2 * n_);
    y0 << u0, v0;
    coefficients_ = vectors_.partialPivLu().solve(y0.cast<std::complex<Real>>());
  }
  // [u(t); v(t)]
  Vector at(Real t) const {
    const Eigen::VectorXcd growth = (values_ * t).array().exp();
    return (vectors_ * growth.cwiseProduct(coefficients_)).real();
  }
  Index size() const { return n_; }

 private:
  Index n_;
  Eigen::MatrixXcd vectors_;
  Eigen::VectorXcd values_;
  Eigen::VectorXcd coefficients_;
};

struct Errors {
  Real u, v;
};

// Max over the coarsest grid's times in [0, endTime] of |u - u_exact| and |v - v_exact|.
Errors trajectoryErrors(LinearSecondOrderSystem& system, const ExactLinearMotion& exact, const Vector& u0,
                        const Vector& v0, Real endTime, int coarsestSteps, int refinement) {
  CentralDifference integrator;
  const int steps = coarsestSteps * refinement;
  integrator.initialise(system, 0, u0, v0, endTime / steps);
  EXPECT_TRUE(integrator.implicitDamping());
  Errors errors{0, 0};
  for (int i = 1; i <= steps; ++i) {
    integrator.step();
    if (i % refinement != 0) continue;
    const Vector y = exact.at(integrator.time());
    const auto s = integrator.state();
    errors.u = std::max(errors.u, (s.displacement - y.head(exact.size())).lpNorm<Eigen::Infinity>());
    errors.v = std::max(errors.v, (s.velocity - y.tail(exact.size())).lpNorm<Eigen::Infinity>());
  }
  return errors;
}

// Observed orders of the last halving (of five grids) for u and v.
Errors dampedObservedOrders(LinearSecondOrderSystem& system, const ExactLinearMotion& exact, const Vector& u0,
                      const Vector& v0, Real endTime, int coarsestSteps, const char* label) {
  std::vector<Errors> errors;
  for (int level = 0; level < 5; ++level)
    errors.push_back(trajectoryErrors(system, exact, u0, v0, endTime, coarsestSteps, 1 << level));
  const Errors& coarse = errors[errors.size() - 2];
  const Errors& fine = errors.back();
  const Errors orders{std::log2(coarse.u / fine.u), std::log2(coarse.v / fine.v)};
  std::printf("%s: errors u %.3e -> %.3e, v %.3e -> %.3e; orders u %.4f v %.4f\n", label, coarse.u, fine.u, coarse.v,
              fine.v, orders.u, orders.v);
  return orders;
}

Eigen::MatrixXd dense(const SparseMatrix& m) { return Eigen::MatrixXd(m); }

TEST(CentralDifferenceImplicitDamping, ScalarDampedOscillatorIsSecondOrderInDisplacementAndVelocity) {
  const Real w = 2 * M_PI, zeta = 0.2;
  auto system = test::oscillator(w, zeta);
  const Vector u0 = Vector::Constant(1, 1.0), v0 = Vector::Constant(1, -0.5);
  const ExactLinearMotion exact(dense(system->mass()), dense(system->damping()), dense(system->stiffness()), u0, v0);
  const Errors orders = dampedObservedOrders(*system, exact, u0, v0, 2.0, 40, "scalar damped oscillator");
  EXPECT_NEAR(orders.u, 2.0, 0.05);
  EXPECT_NEAR(orders.v, 2.0, 0.05);
}

// Two coupled masses with a damping matrix that is neither diagonal nor proportional to M or K
// (the modes of the undamped system do not decouple it).
std::unique_ptr<LinearSecondOrderSystem> coupledPair() {
  Eigen::MatrixXd m(2, 2), c(2, 2), k(2, 2);
  m << 1, 0, 0, 2;
  c << 0.8, -0.5, -0.5, 0.6;
  k << 30, -10, -10, 20;
  return std::make_unique<LinearSecondOrderSystem>(m.sparseView(), c.sparseView(), k.sparseView());
}

TEST(CentralDifferenceImplicitDamping, CoupledPairWithNonDiagonalDampingIsSecondOrder) {
  auto system = coupledPair();
  Vector u0(2), v0(2);
  u0 << 1, -0.5;
  v0 << 0.3, 2;
  const ExactLinearMotion exact(dense(system->mass()), dense(system->damping()), dense(system->stiffness()), u0, v0);
  const Errors orders = dampedObservedOrders(*system, exact, u0, v0, 3.0, 60, "coupled pair, non-diagonal C");
  EXPECT_NEAR(orders.u, 2.0, 0.05);
  EXPECT_NEAR(orders.v, 2.0, 0.05);
}

struct StrongDashpotRun {
  Real firstStep;  // |u_1|
  Real amplitude;  // max |u_n| (1e300 once not finite)
  Real last;       // |u| after the last step
};

// m u'' + c u' + k u = 0 with m = 1, w = 1, c dt / m = 10 and w dt = 1.5, from u0 = 1, v0 = 1.
StrongDashpotRun strongDashpotRun(DashpotOperator damping, int steps) {
  const Real w = 1, dt = 1.5 / w, c = 10 / dt;
  LinearSecondOrderSystem system(test::scalarMatrix(1), test::scalarMatrix(c), test::scalarMatrix(w * w));
  CentralDifference integrator(damping);
  integrator.initialise(system, 0, Vector::Ones(1), Vector::Ones(1), dt);
  EXPECT_EQ(integrator.implicitDamping(), damping == DashpotOperator::implicit);
  StrongDashpotRun run{0, 0, 0};
  for (int i = 0; i < steps && run.amplitude < 1e30; ++i) {
    integrator.step();
    const Real u = std::abs(integrator.state().displacement[0]);
    if (i == 0) run.firstStep = u;
    run.amplitude = std::isfinite(u) ? std::max(run.amplitude, u) : 1e300;
    run.last = u;
  }
  return run;
}

TEST(CentralDifferenceImplicitDamping, StrongDashpotsStayBoundedWhereThePredictorBlowsUp) {
  // The implicit scheme's characteristic polynomial (1 + c dt/2) z^2 - (2 - w^2 dt^2) z + (1 - c dt/2)
  // has both roots inside the unit circle for any c >= 0 when w dt < 2 (Jury's test): here
  // 6 z^2 + 0.25 z - 4, roots 0.796 and -0.838. The Taylor start u_1 = u0 + dt v0 + dt^2/2 a_0 with
  // the exact a_0 = -w^2 u0 - c v0 = -23/3 is the largest excursion, |u_1| = 6.125; then it decays.
  const StrongDashpotRun implicit = strongDashpotRun(DashpotOperator::implicit, 10000);
  const StrongDashpotRun predictor = strongDashpotRun(DashpotOperator::predictor, 10000);
  std::printf("c dt / m = 10, w dt = 1.5: implicit |u_1| %.6f max |u| %.6f last |u| %.3e; predictor max |u| %.3e\n",
              implicit.firstStep, implicit.amplitude, implicit.last, predictor.amplitude);
  EXPECT_NEAR(implicit.firstStep, 6.125, 1e-12);
  EXPECT_EQ(implicit.amplitude, implicit.firstStep);
  EXPECT_LT(implicit.last, 1e-300);  // 0.838^10000
  EXPECT_GT(predictor.amplitude, 1e30);
}

TEST(CentralDifferenceImplicitDamping, WithoutDampingBothOptionsAreTheClassicalSchemeBitForBit) {
  const int n = 40;
  auto system = test::springChain(n);
  const Vector u0 = test::chainInitialDisplacement(n);
  Vector v0(n);
  for (int i = 0; i < n; ++i) v0[i] = std::sin(0.2 * i);
  CentralDifference implicit(DashpotOperator::implicit), predictor(DashpotOperator::predictor);
  implicit.initialise(*system, 0, u0, v0, 0.4);
  predictor.initialise(*system, 0, u0, v0, 0.4);
  EXPECT_FALSE(implicit.implicitDamping());  // nothing to treat implicitly
  // The classical three-level form u_{n+1} = 2 u_n - u_{n-1} + dt^2 a_n, from the Taylor start.
  const Real dt = 0.4;
  Vector previous = u0, current = u0 + dt * v0 + 0.5 * dt * dt * (-(system->stiffness() * u0));
  for (int i = 1; i <= 500; ++i) {
    implicit.step();
    predictor.step();
    ASSERT_EQ(implicit.state().displacement, predictor.state().displacement);
    ASSERT_EQ(implicit.state().velocity, predictor.state().velocity);
    EXPECT_LT((implicit.state().displacement - current).lpNorm<Eigen::Infinity>(), 1e-12) << "step " << i;
    Vector next = 2 * current - previous - dt * dt * (system->stiffness() * current);
    previous = current;
    current = next;
  }
}

TEST(CentralDifferenceImplicitDamping, ReportedStateSatisfiesTheEquationOfMotionWithBlockDashpots) {
  // Two particles of three components, each with its own full 3 x 3 dashpot block (the lumped
  // transmitting boundary of a corner particle), springs coupling them, and a load: eq. (32),
  // M a_n + C v_n = f(t_n) - K u_n, holds for the reported a_n and v_n at every step.
  Eigen::MatrixXd m = Eigen::VectorXd::LinSpaced(6, 1, 2).asDiagonal(), c = Eigen::MatrixXd::Zero(6, 6);
  Eigen::Matrix3d block;
  block << 4, 1, 0.5, 1, 3, -0.7, 0.5, -0.7, 5;
  c.topLeftCorner(3, 3) = block;
  c.bottomRightCorner(3, 3) = 2 * block;
  Eigen::MatrixXd k = 3 * Eigen::MatrixXd::Identity(6, 6);
  for (int i = 0; i < 3; ++i) k(i, i + 3) = k(i + 3, i) = -1;
  LinearSecondOrderSystem system(m.sparseView(), c.sparseView(), k.sparseView(),
                                 [](Real t, Vector& f) { f[4] = std::cos(3 * t); });
  CentralDifference integrator;
  integrator.initialise(system, 0, Vector::LinSpaced(6, -1, 1), Vector::Zero(6), 0.2);  // c dt / m up to 2
  ASSERT_TRUE(integrator.implicitDamping());
  Real worst = 0;
  Vector f;
  for (int i = 0; i < 200; ++i) {
    integrator.step();
    const auto s = integrator.state();
    system.force(s.time, f);
    const Vector residual = m * integrator.acceleration() + c * s.velocity + k * s.displacement - f;
    worst = std::max(worst, residual.lpNorm<Eigen::Infinity>());
    // the synchronous velocity is the mean of the two staggered ones around it
    EXPECT_LT((s.velocity - (integrator.staggeredVelocity() + 0.5 * 0.2 * integrator.acceleration())).norm(), 1e-13);
  }
  EXPECT_LT(worst, 1e-12);
}

TEST(CentralDifferenceImplicitDamping, OptionIsChosenBeforeInitialiseAndByName) {
  auto system = test::oscillator(1.0, 0.1);
  CentralDifference integrator;
  EXPECT_EQ(integrator.damping(), DashpotOperator::implicit);
  integrator.setDamping(DashpotOperator::predictor);
  integrator.initialise(*system, 0, Vector::Ones(1), Vector::Zero(1), 0.1);
  EXPECT_FALSE(integrator.implicitDamping());
  try {
    integrator.setDamping(DashpotOperator::implicit);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "damping");
  }
  EXPECT_EQ(CentralDifference::dampingFromName("predictor"), DashpotOperator::predictor);
  EXPECT_EQ(CentralDifference::dampingFromName("implicit"), DashpotOperator::implicit);
  try {
    CentralDifference::dampingFromName("explicit");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "integrator.damping");
  }
}

TEST(CentralDifferenceImplicitDamping, FactoryPassesTheDampingOption) {
  auto system = test::oscillator(1.0, 0.1);
  IntegratorOptions options;
  EXPECT_EQ(options.centralDifferenceDamping, DashpotOperator::implicit);
  for (DashpotOperator damping : {DashpotOperator::implicit, DashpotOperator::predictor}) {
    options.centralDifferenceDamping = damping;
    auto integrator = makeSecondOrderIntegrator("central_difference", options);
    integrator->initialise(*system, 0, Vector::Ones(1), Vector::Zero(1), 0.01);
    auto* cd = dynamic_cast<CentralDifference*>(integrator.get());
    ASSERT_NE(cd, nullptr);
    EXPECT_EQ(cd->implicitDamping(), damping == DashpotOperator::implicit);
  }
}

}  // namespace
