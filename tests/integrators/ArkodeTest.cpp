// The ARKODE adapter: adaptive accuracy, exact landing, tables, statistics, errors.

#include "TestSystems.hpp"
#include "core/Error.hpp"
#include "integrators/ArkodeExplicit.hpp"
#include "integrators/ArkodeSecondOrder.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>

using namespace mfwave;

namespace {

constexpr Real kArkodeOmega = 2 * M_PI;
constexpr Real kZeta = 0.1;

TEST(ArkodeSecondOrder, AdaptiveDormandPrinceMeetsItsTolerance) {
  auto system = test::oscillator(kArkodeOmega, kZeta);
  ArkodeOptions options;
  options.table = "dormand_prince_7_4_5";
  options.adaptive = true;
  options.relativeTolerance = 1e-8;
  options.absoluteTolerance = 1e-10;
  ArkodeSecondOrder integrator(options);
  integrator.initialise(*system, 0, Vector::Ones(1), Vector::Zero(1), 1e-3);
  Real maxError = 0;
  for (Real t : {0.3, 0.7, 1.25, 2.0}) {
    integrator.advanceTo(t);
    EXPECT_EQ(integrator.time(), t);  // lands exactly
    const auto exact = test::oscillatorExact(kArkodeOmega, kZeta, t);
    maxError = std::max(maxError, std::abs(integrator.state().displacement[0] - exact.u));
    maxError = std::max(maxError, std::abs(integrator.state().velocity[0] - exact.v) / kArkodeOmega);
  }
  const auto stats = integrator.arkode().statistics();
  std::printf("dormand_prince rtol 1e-8: max error %.3e, %ld steps, %ld rhs, %ld failed\n", maxError, stats.steps,
              stats.rhsEvaluations, stats.failedSteps);
  EXPECT_LT(maxError, 1e-6);
  EXPECT_GT(maxError, 1e-13);  // a real computation, not an exact formula
  EXPECT_GT(stats.steps, 10);
  EXPECT_GE(stats.rhsEvaluations, 6 * stats.steps);  // 7 stages, first same as last
  EXPECT_EQ(integrator.stepCount(), stats.steps);

  // A looser tolerance is cheaper and less accurate: the control really acts.
  options.relativeTolerance = 1e-4;
  options.absoluteTolerance = 1e-6;
  ArkodeSecondOrder loose(options);
  loose.initialise(*system, 0, Vector::Ones(1), Vector::Zero(1), 1e-3);
  loose.advanceTo(2.0);
  EXPECT_LT(loose.arkode().statistics().steps, stats.steps);
  const auto exact = test::oscillatorExact(kArkodeOmega, kZeta, 2.0);
  EXPECT_GT(std::abs(loose.state().displacement[0] - exact.u), 1e-9);
}

TEST(ArkodeSecondOrder, AdaptiveStepsAdvanceByTheChosenStep) {
  auto system = test::oscillator(kArkodeOmega, kZeta);
  ArkodeOptions options;
  options.table = "bogacki_shampine_4_2_3";
  options.adaptive = true;
  ArkodeSecondOrder integrator(options);
  integrator.initialise(*system, 0, Vector::Ones(1), Vector::Zero(1), 1e-4);
  Real previous = integrator.time();
  for (int i = 0; i < 20; ++i) {
    integrator.step();
    EXPECT_NEAR(integrator.time() - previous, integrator.stepSize(), 1e-15);
    previous = integrator.time();
  }
  EXPECT_EQ(integrator.stepCount(), 20);
  EXPECT_GT(integrator.stepSize(), 1e-4);  // grew from the initial step
  // advanceTo after single steps, then steps after advanceTo (the stop time must not stick).
  const Real target = integrator.time() + 0.05;
  integrator.advanceTo(target);
  EXPECT_EQ(integrator.time(), target);
  integrator.step();
  EXPECT_GT(integrator.time(), target);
}

TEST(ArkodeSecondOrder, FixedStepLandsOffGridAndContinuesOnTheGrid) {
  auto system = test::oscillator(kArkodeOmega, 0);
  ArkodeSecondOrder integrator;  // classic_rk4
  integrator.initialise(*system, 0, Vector::Ones(1), Vector::Zero(1), 0.01);
  integrator.advanceTo(0.255);
  EXPECT_EQ(integrator.time(), 0.255);
  const auto exact = test::oscillatorExact(kArkodeOmega, 0, 0.255);
  EXPECT_NEAR(integrator.state().displacement[0], exact.u, 1e-6);
  integrator.step();
  EXPECT_NEAR(integrator.time(), 0.265, 1e-12);
  EXPECT_NEAR(integrator.stepSize(), 0.01, 0);
  // Classic RK4: four right-hand sides per step.
  ArkodeSecondOrder counted;
  counted.initialise(*system, 0, Vector::Ones(1), Vector::Zero(1), 0.01);
  for (int i = 0; i < 50; ++i) counted.step();
  const auto stats = counted.arkode().statistics();
  EXPECT_EQ(stats.steps, 50);
  EXPECT_GE(stats.rhsEvaluations, 200);
  EXPECT_LE(stats.rhsEvaluations, 202);
  EXPECT_EQ(stats.failedSteps, 0);
  EXPECT_NEAR(counted.time(), 0.5, 1e-13);
}

TEST(ArkodeSecondOrder, ClassicRk4IsTheTextbookMethod) {
  // Against RK4 written out by hand. Guards the workaround for SUNDIALS 6.4.1 reusing the last
  // stage as the next first stage when c_s = 1 (without it the two differ by 1e-2 after 10 steps).
  const Real w = kArkodeOmega, dt = 0.05;
  auto system = test::oscillator(w, kZeta);
  ArkodeSecondOrder integrator;
  integrator.initialise(*system, 0, Vector::Ones(1), Vector::Zero(1), dt);
  Eigen::Vector2d y(1, 0);
  auto f = [&](const Eigen::Vector2d& q) {
    return Eigen::Vector2d(q[1], -w * w * q[0] - 2 * kZeta * w * q[1]);
  };
  for (int i = 0; i < 10; ++i) {
    integrator.step();
    const Eigen::Vector2d k1 = f(y), k2 = f(y + dt / 2 * k1), k3 = f(y + dt / 2 * k2), k4 = f(y + dt * k3);
    y += dt / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    EXPECT_NEAR(integrator.state().displacement[0], y[0], 1e-14);
    EXPECT_NEAR(integrator.state().velocity[0], y[1], 1e-13);
  }
}

TEST(ArkodeExplicit, IntegratesAPlainFirstOrderSystem) {
  // y' = -y + sin t, a system that is not a second-order one in disguise.
  struct Forced : FirstOrderSystem {
    Index size() const override { return 2; }
    void rhs(Real t, Eigen::Ref<const Vector> y, Eigen::Ref<Vector> ydot) override {
      ydot[0] = -y[0] + std::sin(t);
      ydot[1] = -2 * y[1];
    }
  } system;
  ArkodeOptions options;
  options.table = "verner_8_5_6";
  options.fixedStep = 0.05;
  ArkodeExplicit integrator(options);
  EXPECT_EQ(integrator.order(), 6);
  Vector y0(2);
  y0 << 1, 1;
  integrator.initialise(system, 0, y0);
  integrator.advanceTo(1.0);
  // y0(t) = (3/2) e^{-t} + (sin t - cos t) / 2, y1 = e^{-2t}.
  EXPECT_NEAR(integrator.state()[0], 1.5 * std::exp(-1.0) + 0.5 * (std::sin(1.0) - std::cos(1.0)), 1e-10);
  EXPECT_NEAR(integrator.state()[1], std::exp(-2.0), 1e-10);
  EXPECT_EQ(integrator.time(), 1.0);
}

TEST(ArkodeExplicit, BadTablesAndOptionsNameTheirKey) {
  ArkodeOptions options;
  options.table = "runge_kutta_99";
  try {
    ArkodeExplicit bad(options);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "integrator.table");
    const std::string what = e.what();
    EXPECT_NE(what.find("runge_kutta_99"), std::string::npos);
    EXPECT_NE(what.find("classic_rk4"), std::string::npos);
    EXPECT_NE(what.find("dormand_prince_7_4_5"), std::string::npos);
  }
  options.table = "classic_rk4";
  options.adaptive = true;  // no embedding
  try {
    ArkodeExplicit bad(options);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "integrator.table");
  }
  options.table = "heun_euler_2_1_2";
  options.relativeTolerance = -1;
  try {
    ArkodeExplicit bad(options);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "integrator.relative_tolerance");
  }
  // Every advertised table loads, with a sensible order.
  for (const auto& name : ArkodeExplicit::tableNames()) {
    ArkodeOptions o;
    o.table = name;
    ArkodeExplicit integrator(o);
    EXPECT_GE(integrator.order(), 2) << name;
    EXPECT_LE(integrator.order(), 8) << name;
  }
}

TEST(ArkodeSecondOrder, ExceptionsFromTheSystemCrossSundialsIntact) {
  // A lumped mass with a zero entry: LinearSecondOrderSystem::acceleration throws InputError("mass", ...).
  SparseMatrix m(2, 2);
  m.insert(0, 0) = 2;
  m.insert(1, 1) = 0;
  SparseMatrix k(2, 2);
  k.setIdentity();
  LinearSecondOrderSystem system(m, SparseMatrix(), k);
  ArkodeSecondOrder integrator;
  integrator.initialise(system, 0, Vector::Ones(2), Vector::Zero(2), 0.1);
  try {
    integrator.step();
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "mass");
  }
}

TEST(ArkodeExplicit, SundialsFailuresBecomeErrorsNamingTheFunction) {
  // An adaptive run that may take only 5 steps per advance: ARK_TOO_MUCH_WORK.
  auto system = test::oscillator(kArkodeOmega, kZeta);
  ArkodeOptions options;
  options.table = "heun_euler_2_1_2";
  options.adaptive = true;
  options.relativeTolerance = 1e-10;
  options.maxStepsPerAdvance = 5;
  ArkodeSecondOrder integrator(options);
  integrator.initialise(*system, 0, Vector::Ones(1), Vector::Zero(1), 1e-3);
  try {
    integrator.advanceTo(10.0);
    FAIL();
  } catch (const InputError&) {
    FAIL() << "not an input error";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("ERKStepEvolve"), std::string::npos) << what;
    EXPECT_NE(what.find("ARK_TOO_MUCH_WORK"), std::string::npos) << what;
  }
}

// test_integrators links no MPI, so no MPI vectors are installed: a system that says it holds one
// rank's share is refused by name rather than run on serial vectors, which would give each rank its
// own norms and its own adaptive steps (the MPI side: tests/decomposition/mpi/ArkodeMpiTest.cpp).
TEST(ArkodeExplicit, ADistributedSystemWithoutMpiVectorsIsRefused) {
  struct Distributed : FirstOrderSystem {
    Index size() const override { return 2; }
    void rhs(Real, Eigen::Ref<const Vector> y, Eigen::Ref<Vector> ydot) override { ydot = -y; }
    std::optional<VectorDistribution> distribution() const override { return VectorDistribution{&handle, 4, {}}; }
    int handle = 0;  // stands for a communicator; never read without MPI vectors
  } system;
  ArkodeOptions options;
  options.fixedStep = 0.1;
  ArkodeExplicit integrator(options);
  try {
    integrator.initialise(system, 0, Vector::Ones(2));
    FAIL() << "a distributed system ran on serial vectors";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("no MPI vectors"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(integrator.isInitialised());
}

}  // namespace
