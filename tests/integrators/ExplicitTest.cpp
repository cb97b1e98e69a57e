// Central difference and leapfrog: stability limit, energy behaviour, equivalence, cost.

#include "TestSystems.hpp"
#include "core/Error.hpp"
#include "integrators/CentralDifference.hpp"
#include "integrators/Leapfrog.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

using namespace mfwave;

namespace {

template <class Integrator>
std::unique_ptr<SecondOrderIntegrator> make() {
  return std::make_unique<Integrator>();
}

template <class T>
class ExplicitScheme : public ::testing::Test {};
using Schemes = ::testing::Types<CentralDifference, Leapfrog>;
TYPED_TEST_SUITE(ExplicitScheme, Schemes);

constexpr Real kExplicitOmega = 3.0;

// Max |u| over `steps` steps of the undamped oscillator with w dt = wdt, from u0 = 1, v0 = w.
template <class Integrator>
Real maxAmplitude(Real wdt, int steps) {
  auto system = test::oscillator(kExplicitOmega, 0);
  Integrator integrator;
  Vector u0(1), v0(1);
  u0 << 1;
  v0 << kExplicitOmega;
  integrator.initialise(*system, 0, u0, v0, wdt / kExplicitOmega);
  Real amplitude = 0;
  for (int i = 0; i < steps && amplitude < 1e30; ++i) {
    integrator.step();
    amplitude = std::max(amplitude, std::abs(integrator.state().displacement[0]));
  }
  return amplitude;
}

TYPED_TEST(ExplicitScheme, BlowsUpJustAboveTheStabilityLimit) {
  // w dt = 2.02: an eigenvalue of modulus about 1.33 per step.
  EXPECT_GT(maxAmplitude<TypeParam>(2 * 1.01, 300), 1e3);
}

TYPED_TEST(ExplicitScheme, StaysBoundedJustBelowTheStabilityLimit) {
  // The scheme conserves v^2 + w^2 (1 - x) u^2 with x = (w dt / 2)^2, so from (u0, v0) = (1, w)
  // |u| <= sqrt(1 + 1 / (1 - x)) <= sqrt(2) / sqrt(1 - x): about 10 here, against 1.41 exactly.
  const Real wdt = 2 * 0.99;
  const Real x = wdt * wdt / 4;
  const Real amplitude = maxAmplitude<TypeParam>(wdt, 10000);
  EXPECT_LE(amplitude, std::sqrt(1 + 1 / (1 - x)) * (1 + 1e-9));
  EXPECT_GT(amplitude, 2.0);  // the numerical solution does feel the limit (exact amplitude is 1.41)
}

TYPED_TEST(ExplicitScheme, EnergyErrorIsBoundedWithoutDrift) {
  // Symplectic: the energy 1/2 v^2 + 1/2 w^2 u^2 (with the synchronous velocity) oscillates within
  // a relative band of (w dt)^2 / 4 from (u0, v0) = (1, 0) and does not drift over 10^5 steps.
  const Real wdt = 0.1;
  auto system = test::oscillator(kExplicitOmega, 0);
  TypeParam integrator;
  Vector u0(1), v0(1);
  u0 << 1;
  v0 << 0;
  integrator.initialise(*system, 0, u0, v0, wdt / kExplicitOmega);
  const Real e0 = system->kineticEnergy(v0) + system->strainEnergy(u0);
  const int steps = 100000;
  Real maxFirst = 0, maxLast = 0, maxAll = 0;
  for (int i = 1; i <= steps; ++i) {
    integrator.step();
    const auto s = integrator.state();
    const Real error = std::abs(system->kineticEnergy(s.velocity) + system->strainEnergy(s.displacement) - e0) / e0;
    maxAll = std::max(maxAll, error);
    if (i <= 1000) maxFirst = std::max(maxFirst, error);
    if (i > steps - 1000) maxLast = std::max(maxLast, error);
  }
  std::printf("energy error band: first %.6e last %.6e all %.6e bound %.6e\n", maxFirst, maxLast, maxAll,
              wdt * wdt / 4);
  EXPECT_LE(maxAll, 1.01 * wdt * wdt / 4);
  EXPECT_GT(maxFirst, 0.5 * wdt * wdt / 4);  // the band is really there (the bound is tight)
  EXPECT_NEAR(maxLast, maxFirst, 1e-3 * maxFirst);
}

TYPED_TEST(ExplicitScheme, OneAccelerationEvaluationPerStep) {
  // A counting wrapper around a damped chain (velocity-dependent: exercises the predictor).
  struct Counting : SecondOrderSystem {
    explicit Counting(SecondOrderSystem& s) : inner(s) {}
    Index size() const override { return inner.size(); }
    bool dependsOnVelocity() const override { return inner.dependsOnVelocity(); }
    void acceleration(Real t, Eigen::Ref<const Vector> u, Eigen::Ref<const Vector> v, Eigen::Ref<Vector> a) override {
      ++calls;
      inner.acceleration(t, u, v, a);
    }
    SecondOrderSystem& inner;
    long calls = 0;
  };
  SparseMatrix c(2, 2), k(2, 2), m(2, 2);
  m.setIdentity();
  c.setIdentity();
  k.insert(0, 0) = 2;
  k.insert(1, 1) = 2;
  k.insert(0, 1) = -1;
  k.insert(1, 0) = -1;
  LinearSecondOrderSystem damped(m, c * 0.1, k);
  Counting counting(damped);
  TypeParam integrator;
  integrator.initialise(counting, 0, Vector::Ones(2), Vector::Zero(2), 0.1);
  EXPECT_EQ(counting.calls, 1);
  for (int i = 0; i < 25; ++i) integrator.step();
  EXPECT_EQ(counting.calls, 26);
  EXPECT_EQ(integrator.stepCount(), 25);
  EXPECT_DOUBLE_EQ(integrator.time(), 2.5);
}

TYPED_TEST(ExplicitScheme, FirstStepIsTheTaylorStart) {
  // u_1 = u_0 + dt v_0 + dt^2/2 a_0 and v_1 = v_0 + dt/2 (a_0 + a_1), exactly.
  auto system = test::oscillator(kExplicitOmega, 0);
  TypeParam integrator;
  Vector u0(1), v0(1);
  u0 << 0.7;
  v0 << -0.4;
  const Real dt = 0.05;
  integrator.initialise(*system, 1.0, u0, v0, dt);
  integrator.step();
  const Real a0 = -kExplicitOmega * kExplicitOmega * 0.7;
  const Real u1 = 0.7 + dt * -0.4 + 0.5 * dt * dt * a0;
  const Real a1 = -kExplicitOmega * kExplicitOmega * u1;
  EXPECT_NEAR(integrator.state().displacement[0], u1, 1e-15);
  EXPECT_NEAR(integrator.state().velocity[0], -0.4 + 0.5 * dt * (a0 + a1), 1e-15);
  EXPECT_DOUBLE_EQ(integrator.time(), 1.0 + dt);
}

TYPED_TEST(ExplicitScheme, AdvanceToTakesWholeStepsAndRejectsOffGridTimes) {
  auto system = test::oscillator(kExplicitOmega, 0);
  TypeParam integrator;
  integrator.initialise(*system, 0, Vector::Ones(1), Vector::Zero(1), 0.01);
  integrator.advanceTo(0.37);
  EXPECT_EQ(integrator.stepCount(), 37);
  EXPECT_NEAR(integrator.time(), 0.37, 1e-15);
  EXPECT_THROW(integrator.advanceTo(0.375), InputError);
}

TYPED_TEST(ExplicitScheme, BadInitialStateNamesTheKey) {
  auto system = test::oscillator(kExplicitOmega, 0);
  TypeParam integrator;
  try {
    integrator.initialise(*system, 0, Vector::Ones(2), Vector::Zero(1), 0.01);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "initial_state");
  }
  try {
    integrator.initialise(*system, 0, Vector::Ones(1), Vector::Zero(1), 0);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "time_step");
  }
  EXPECT_THROW(integrator.step(), Error);  // never initialised
}

TEST(ExplicitSchemes, LeapfrogAndCentralDifferenceShareTheDisplacementTrajectory) {
  const int n = 50;
  auto system = test::springChain(n);
  const Vector u0 = test::chainInitialDisplacement(n);
  Vector v0(n);
  for (int i = 0; i < n; ++i) v0[i] = std::cos(0.3 * i);
  CentralDifference cd;
  Leapfrog lf;
  cd.initialise(*system, 0, u0, v0, 0.5);
  lf.initialise(*system, 0, u0, v0, 0.5);
  Real maxDifference = 0, maxVelocityDifference = 0;
  for (int i = 0; i < 2000; ++i) {
    cd.step();
    lf.step();
    maxDifference = std::max(maxDifference, (cd.state().displacement - lf.state().displacement).lpNorm<Eigen::Infinity>());
    maxVelocityDifference =
        std::max(maxVelocityDifference, (cd.state().velocity - lf.state().velocity).lpNorm<Eigen::Infinity>());
  }
  std::printf("CD vs leapfrog: max |du| %.3e, max |dv| %.3e\n", maxDifference, maxVelocityDifference);
  EXPECT_LT(maxDifference, 1e-12);
  EXPECT_LT(maxVelocityDifference, 1e-12);
  EXPECT_GT(cd.state().displacement.norm(), 0.1);  // something moved
}

}  // namespace
