// Checkpoints of the integrators (issue 20): an integrator restored from a saved state, on the
// same system and step, takes bitwise the steps the saved one would have taken. Each scheme's
// history is exercised where it lives: the staggered velocity of central difference, its
// prescribed-displacement window and implicit dashpots, Newmark's acceleration, ARKODE's clock and
// counters, the leapfrog's momentum and configuration rates, a step-size rule's clock.

#include "FirstOrderTestSystems.hpp"
#include "TestSystems.hpp"
#include "core/Error.hpp"
#include "integrators/ArkodeFirstOrder.hpp"
#include "integrators/ArkodeSecondOrder.hpp"
#include "integrators/CentralDifference.hpp"
#include "integrators/Newmark.hpp"
#include "integrators/PredictorCorrector.hpp"
#include "integrators/SplitLeapfrog.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <memory>

namespace mfwave {
namespace {

void expectBitwiseEqual(const Vector& a, const Vector& b, const char* what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (Index i = 0; i < a.size(); ++i) EXPECT_EQ(a[i], b[i]) << what << "[" << i << "]";
}

// Runs `n` steps, saves, runs `m` more; a second integrator made and initialised alike is restored
// from the save and runs `m` steps: both must agree bit for bit, clock and counters included.
void expectRestoredRunIsTheSame(const std::function<std::unique_ptr<Integrator>()>& make, int n, int m) {
  std::unique_ptr<Integrator> original = make();
  for (int i = 0; i < n; ++i) original->step();
  StateArchive saved;
  original->saveState(saved);
  for (int i = 0; i < m; ++i) original->step();

  std::unique_ptr<Integrator> restored = make();
  restored->step();  // moved on from the start: restoreState must replace all of it
  restored->restoreState(saved);
  EXPECT_EQ(restored->stepCount(), n);
  for (int i = 0; i < m; ++i) restored->step();

  EXPECT_EQ(restored->time(), original->time());
  EXPECT_EQ(restored->stepCount(), original->stepCount());
  EXPECT_EQ(restored->stepSize(), original->stepSize());
  expectBitwiseEqual(restored->state().displacement, original->state().displacement, "u");
  expectBitwiseEqual(restored->state().velocity, original->state().velocity, "v");
}

TEST(IntegratorCheckpoint, CentralDifferenceWithImplicitDashpotsAndAFilter) {
  auto system = test::oscillator(3.0, 0.2);
  const Vector u0 = Vector::Constant(1, 1.0), v0 = Vector::Zero(1);
  expectRestoredRunIsTheSame(
      [&] {
        auto cd = std::make_unique<CentralDifference>();
        cd->setVelocityFilter([](Real, Vector& v) { v *= 0.999; });
        cd->initialise(*system, 0, u0, v0, 0.01);
        EXPECT_TRUE(cd->implicitDamping());
        return cd;
      },
      37, 41);
}

TEST(IntegratorCheckpoint, CentralDifferencePredictorAndPrescribedDisplacement) {
  // The chain's first mass follows g(t) = 0.1 sin(2t): the window g_n, g_{n+1} is the history.
  auto system = test::springChain(6);
  Vector u0 = test::chainInitialDisplacement(6);
  u0[0] = 0;
  const Vector v0 = Vector::Zero(6);
  expectRestoredRunIsTheSame(
      [&] {
        auto cd = std::make_unique<CentralDifference>(CentralDifference::Damping::predictor);
        cd->setPrescribedDisplacement({0}, [](Real t, Vector& g) { g[0] = 0.1 * std::sin(2 * t); });
        cd->initialise(*system, 0, u0, v0, 0.05);
        return cd;
      },
      23, 30);
}

TEST(IntegratorCheckpoint, NewmarkOnADampedOscillator) {
  auto system = test::oscillator(2.0, 0.1);
  const Vector u0 = Vector::Constant(1, 1.0), v0 = Vector::Zero(1);
  expectRestoredRunIsTheSame(
      [&] {
        auto newmark = std::make_unique<Newmark>(0.25, 0.5);
        newmark->initialise(*system, 0, u0, v0, 0.1);
        return newmark;
      },
      17, 29);
}

TEST(IntegratorCheckpoint, ARestoreOnAnotherStepIsRefused) {
  auto system = test::oscillator(2.0, 0);
  const Vector u0 = Vector::Constant(1, 1.0), v0 = Vector::Zero(1);
  CentralDifference a, b;
  a.initialise(*system, 0, u0, v0, 0.1);
  a.step();
  StateArchive saved;
  a.saveState(saved);
  b.initialise(*system, 0, u0, v0, 0.05);
  try {
    b.restoreState(saved);
    FAIL() << "a checkpoint of another step was restored";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "--restart");
  }
}

TEST(IntegratorCheckpoint, ArkodeFixedStepSecondOrderCountsAsOneRun) {
  auto system = test::springChain(5);
  const Vector u0 = test::chainInitialDisplacement(5), v0 = Vector::Zero(5);
  const auto make = [&] {
    auto rk = std::make_unique<ArkodeSecondOrder>();
    rk->initialise(*system, 0, u0, v0, 0.05);
    return rk;
  };
  expectRestoredRunIsTheSame(make, 13, 19);
  // The counters too: ARKODE's repeated set-up evaluation is not counted twice.
  auto original = make();
  for (int i = 0; i < 32; ++i) original->step();
  auto first = make();
  for (int i = 0; i < 13; ++i) first->step();
  StateArchive saved;
  first->saveState(saved);
  auto restored = make();
  restored->restoreState(saved);
  EXPECT_EQ(restored->arkode().statistics().rhsEvaluations, first->arkode().statistics().rhsEvaluations);
  for (int i = 0; i < 19; ++i) restored->step();
  EXPECT_EQ(restored->arkode().statistics().rhsEvaluations, original->arkode().statistics().rhsEvaluations);
  EXPECT_EQ(restored->arkode().statistics().steps, original->arkode().statistics().steps);
}

TEST(IntegratorCheckpoint, AdaptiveArkodeIsRefusedNamingTheKey) {
  auto system = test::oscillator(2.0, 0);
  ArkodeOptions options;
  options.table = "dormand_prince_7_4_5";
  options.adaptive = true;
  ArkodeSecondOrder rk(options);
  rk.initialise(*system, 0, Vector::Constant(1, 1.0), Vector::Zero(1), 0.01);
  rk.step();
  StateArchive archive;
  try {
    rk.saveState(archive);
    FAIL() << "an adaptive ARKODE run was checkpointed";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "integrator.adaptive");
  }
}

TEST(IntegratorCheckpoint, ArkodeFirstOrderWithAStepRule) {
  test::SplitOscillator system(3.0, 0.05);
  Vector y0(2);
  y0 << 1.0, 0.0;
  expectRestoredRunIsTheSame(
      [&] {
        auto rk = std::make_unique<ArkodeFirstOrder>();
        // A rule whose step changes with the state: the clock is not a plain grid.
        rk->setStepSizeFunction([](Real, const Vector& y) { return 0.01 + 0.002 * std::abs(y[0]); });
        rk->initialise(system, 0, y0, 0.01);
        return rk;
      },
      21, 34);
}

TEST(IntegratorCheckpoint, PredictorCorrectorWithAStepRuleKeepsItsClock) {
  test::ForcedPendulum system(0.3, 0.2);
  Vector y0(2);
  y0 << 0.4, 0.1;
  expectRestoredRunIsTheSame(
      [&] {
        auto pc = std::make_unique<PredictorCorrector>();
        pc->setStepSizeFunction([](Real t, const Vector&) { return t < 0.3 ? 0.02 : 0.03; });
        pc->initialise(system, 0, y0, 0.02);
        return pc;
      },
      12, 25);
}

TEST(IntegratorCheckpoint, SplitLeapfrogKeepsItsRates) {
  test::SelfCoupledDrift system(0.7);
  Vector y0(2);
  y0 << 0.5, -0.2;
  expectRestoredRunIsTheSame(
      [&] {
        auto leapfrog = std::make_unique<SplitLeapfrog>();
        leapfrog->initialise(system, 0, y0, 0.03);
        return leapfrog;
      },
      9, 31);
}

}  // namespace
}  // namespace mfwave
