// The first-order integrators: exact single steps, evaluation counts, exact landing, step rules,
// the factory, input errors, the StateView, and ARKODE with a changing fixed step.

#include "FirstOrderTestSystems.hpp"
#include "core/Error.hpp"
#include "integrators/ArkodeFirstOrder.hpp"
#include "integrators/FirstOrderIntegratorFactory.hpp"
#include "integrators/ForwardEuler.hpp"
#include "integrators/PredictorCorrector.hpp"
#include "integrators/SplitLeapfrog.hpp"
#include "observers/StabilityMonitor.hpp"
#include "observers/TimeLoop.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

using namespace mfwave;

namespace {

constexpr Real kOmega = 2 * M_PI;

// y' = F(t, y) with a nonlinear, time-dependent F of three components (not split).
struct Nonlinear : FirstOrderSystem {
  long calls = 0;
  Index size() const override { return 3; }
  void rhs(Real t, Eigen::Ref<const Vector> y, Eigen::Ref<Vector> ydot) override {
    ++calls;
    ydot[0] = std::sin(t) * y[1] - y[0] * y[2];
    ydot[1] = y[0] * y[0] + std::cos(3 * t);
    ydot[2] = -0.5 * y[2] + t;
  }
};

Vector nonlinearStart() {
  Vector y(3);
  y << 0.3, -1.2, 0.7;
  return y;
}

Vector F(Nonlinear& system, Real t, const Vector& y) {
  Vector ydot(3);
  system.rhs(t, y, ydot);
  return ydot;
}

TEST(FirstOrderIntegrators, ForwardEulerStepIsExactlyYPlusDtF) {
  Nonlinear system;
  ForwardEuler integrator;
  const Real t0 = 0.37, dt = 0.013;
  integrator.initialise(system, t0, nonlinearStart(), dt);
  Nonlinear reference;
  Vector y = nonlinearStart();
  Real t = t0;
  for (int i = 0; i < 5; ++i) {
    integrator.step();
    y = y + dt * F(reference, t, y);
    t = t0 + (i + 1) * dt;
    for (Index k = 0; k < 3; ++k) EXPECT_EQ(integrator.solution()[k], y[k]);  // bit for bit
    EXPECT_EQ(integrator.time(), t);
  }
  EXPECT_EQ(integrator.stepCount(), 5);
  EXPECT_EQ(integrator.rhsEvaluations(), 5.0);
  EXPECT_EQ(system.calls, 5);
  EXPECT_EQ(integrator.stepSize(), dt);
  EXPECT_EQ(integrator.name(), "forward_euler");
}

TEST(FirstOrderIntegrators, PredictorCorrectorIsTheMidpointRule) {
  Nonlinear system, reference;
  PredictorCorrector integrator;
  const Real dt = 0.02;
  integrator.initialise(system, 0, nonlinearStart(), dt);
  Vector y = nonlinearStart();
  for (int i = 0; i < 5; ++i) {
    integrator.step();
    const Real t = i * dt;
    const Vector predicted = y + 0.5 * dt * F(reference, t, y);
    y = y + dt * F(reference, t + 0.5 * dt, predicted);
    EXPECT_LT((integrator.solution() - y).norm(), 1e-15);
  }
  EXPECT_EQ(integrator.rhsEvaluations(), 10.0);
  EXPECT_EQ(system.calls, 10);
}

TEST(FirstOrderIntegrators, SplitLeapfrogFollowsTheKickDriftKickFormulas) {
  // Written out by hand on the damped oscillator (P depends on p: exercises the predictor).
  const Real w = 3, zeta = 0.2, dt = 0.05;
  test::SplitOscillator system(w, zeta);
  SplitLeapfrog integrator;
  integrator.initialise(system, 0, test::vector2(1, 0.5), dt);
  EXPECT_EQ(integrator.rhsEvaluations(), 0.5);  // P_0
  EXPECT_EQ(system.momentumCalls, 1);
  auto P = [&](Real q, Real p) { return -w * w * q - 2 * zeta * w * p; };
  Real q = 1, p = 0.5, Pn = P(q, p);
  for (int i = 0; i < 6; ++i) {
    integrator.step();
    const Real pHalf = p + dt / 2 * Pn;
    q = q + dt * pHalf;
    const Real pStar = pHalf + dt / 2 * Pn;
    Pn = P(q, pStar);
    p = pHalf + dt / 2 * Pn;
    EXPECT_NEAR(integrator.solution()[0], q, 1e-15);
    EXPECT_NEAR(integrator.solution()[1], p, 1e-15);
    EXPECT_NEAR(integrator.momentumRate()[0], Pn, 1e-14);
  }
  // One configuration and one momentum evaluation per step, plus P_0.
  EXPECT_EQ(system.configurationCalls, 6);
  EXPECT_EQ(system.momentumCalls, 7);
  EXPECT_EQ(integrator.rhsEvaluations(), 6.5);
}

TEST(FirstOrderIntegrators, SplitLeapfrogEvaluatesAtTheRightTimes) {
  // q' = p + a cos 2t is drifted at t_n + dt/2, p' = ... + b cos 1.3t kicked at t_n and t_{n+1}.
  struct Recording : test::ForcedPendulum {
    Recording() : ForcedPendulum(0.2, 0.5) {}
    std::vector<Real> qTimes, pTimes;
    void configurationRate(Real t, Eigen::Ref<const Vector> y, Eigen::Ref<Vector> qdot) override {
      qTimes.push_back(t);
      ForcedPendulum::configurationRate(t, y, qdot);
    }
    void momentumRate(Real t, Eigen::Ref<const Vector> y, Eigen::Ref<Vector> pdot) override {
      pTimes.push_back(t);
      ForcedPendulum::momentumRate(t, y, pdot);
    }
  } system;
  SplitLeapfrog integrator;
  integrator.initialise(system, 1.0, test::vector2(0.1, 0), 0.1);
  integrator.step();
  integrator.step();
  ASSERT_EQ(system.qTimes.size(), 2u);
  ASSERT_EQ(system.pTimes.size(), 3u);
  EXPECT_DOUBLE_EQ(system.qTimes[0], 1.05);
  EXPECT_DOUBLE_EQ(system.qTimes[1], 1.15);
  EXPECT_DOUBLE_EQ(system.pTimes[0], 1.0);
  EXPECT_DOUBLE_EQ(system.pTimes[1], 1.1);
  EXPECT_DOUBLE_EQ(system.pTimes[2], 1.2);
}

TEST(FirstOrderIntegrators, LeapfrogRefusesAnUnsplitSystem) {
  test::PlainOscillator system(1);
  auto leapfrog = makeFirstOrderIntegrator("leapfrog");
  try {
    leapfrog->initialise(system, 0, test::vector2(1, 0), 0.1);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "integrator.name");
    EXPECT_NE(std::string(e.what()).find("SplitFirstOrderSystem"), std::string::npos);
  }
  // The others take it.
  for (const std::string name : {"forward_euler", "predictor_corrector", "arkode"}) {
    auto integrator = makeFirstOrderIntegrator(name);
    integrator->initialise(system, 0, test::vector2(1, 0), 0.1);
    integrator->step();
    EXPECT_EQ(integrator->stepCount(), 1) << name;
  }
}

TEST(FirstOrderIntegrators, EvaluationCounts) {
  const int steps = 50;
  struct Expected {
    std::string name;
    double evaluations;
  };
  for (const auto& [name, evaluations] : std::vector<Expected>{
           {"forward_euler", steps}, {"predictor_corrector", 2.0 * steps}, {"leapfrog", steps + 0.5}}) {
    test::SplitOscillator system(kOmega, 0.1);
    auto integrator = makeFirstOrderIntegrator(name);
    integrator->initialise(system, 0, test::vector2(1, 0), 0.01);
    for (int i = 0; i < steps; ++i) integrator->step();
    EXPECT_EQ(integrator->rhsEvaluations(), evaluations) << name;
    EXPECT_EQ(0.5 * (system.configurationCalls + system.momentumCalls), evaluations) << name;
  }
  test::SplitOscillator system(kOmega, 0.1);
  ArkodeFirstOrder rk4;
  rk4.initialise(system, 0, test::vector2(1, 0), 0.01);
  for (int i = 0; i < steps; ++i) rk4.step();
  EXPECT_GE(rk4.rhsEvaluations(), 4.0 * steps);
  EXPECT_LE(rk4.rhsEvaluations(), 4.0 * steps + 2);
  EXPECT_EQ(rk4.rhsEvaluations(), static_cast<double>(system.configurationCalls));
  EXPECT_EQ(rk4.stepCount(), steps);
}

TEST(FirstOrderIntegrators, FactoryNamesAndErrors) {
  const std::vector<std::string> expected{"forward_euler", "predictor_corrector", "leapfrog", "arkode"};
  EXPECT_EQ(firstOrderIntegratorNames(), expected);
  for (const auto& name : firstOrderIntegratorNames()) {
    auto integrator = makeFirstOrderIntegrator(name);
    ASSERT_TRUE(integrator) << name;
    EXPECT_EQ(integrator->name(), name);
    test::SplitOscillator system(1.0, 0.1);
    integrator->initialise(system, 0, test::vector2(1, 0), 0.001);
    integrator->advanceTo(1.0);
    EXPECT_EQ(integrator->time(), 1.0) << name;
    EXPECT_NEAR(integrator->solution()[0], system.exact(1.0)[0], 1e-3) << name;
  }
  try {
    makeFirstOrderIntegrator("runge_kutta");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "integrator.name");
    const std::string what = e.what();
    EXPECT_NE(what.find("unknown integrator 'runge_kutta'; valid: forward_euler, predictor_corrector, leapfrog, arkode"),
              std::string::npos)
        << what;
  }
  // ARKODE options pass through and are checked at construction.
  ArkodeOptions options;
  options.table = "nope";
  try {
    makeFirstOrderIntegrator("arkode", options);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "integrator.table");
  }
  options.table = "verner_8_5_6";
  auto verner = makeFirstOrderIntegrator("arkode", options);
  EXPECT_EQ(dynamic_cast<ArkodeFirstOrder&>(*verner).arkode().order(), 6);
}

TEST(FirstOrderIntegrators, InitialiseChecksTheStateAndTheStep) {
  auto expectKey = [](FirstOrderIntegrator& integrator, FirstOrderSystem& system, const Vector& y0, Real dt,
                      const std::string& key) {
    try {
      integrator.initialise(system, 0, y0, dt);
      ADD_FAILURE() << integrator.name() << ": no error for key " << key;
    } catch (const InputError& e) {
      EXPECT_EQ(e.key(), key) << integrator.name() << ": " << e.what();
    }
  };
  const Real nan = std::numeric_limits<Real>::quiet_NaN();
  const Real inf = std::numeric_limits<Real>::infinity();
  for (const auto& name : firstOrderIntegratorNames()) {
    test::SplitOscillator system(1, 0);
    auto integrator = makeFirstOrderIntegrator(name);
    expectKey(*integrator, system, Vector::Ones(3), 0.1, "initial_state");
    expectKey(*integrator, system, Vector(), 0.1, "initial_state");
    expectKey(*integrator, system, test::vector2(1, nan), 0.1, "initial_state");
    expectKey(*integrator, system, test::vector2(inf, 0), 0.1, "initial_state");
    expectKey(*integrator, system, test::vector2(1, 0), 0, "time_step");
    expectKey(*integrator, system, test::vector2(1, 0), -0.1, "time_step");
    expectKey(*integrator, system, test::vector2(1, 0), nan, "time_step");
    expectKey(*integrator, system, test::vector2(1, 0), inf, "time_step");
    try {
      integrator->initialise(system, nan, test::vector2(1, 0), 0.1);
      ADD_FAILURE() << name;
    } catch (const InputError& e) {
      EXPECT_EQ(e.key(), "start_time");
    }
    // step() before a successful initialise names the integrator.
    try {
      integrator->step();
      ADD_FAILURE() << name;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
  }
}

TEST(FirstOrderIntegrators, AStepRuleReturningZeroOrNanThrowsNamingTheStep) {
  for (const auto& name : firstOrderIntegratorNames()) {
    for (const Real bad : {0.0, -1.0, std::numeric_limits<Real>::quiet_NaN(), std::numeric_limits<Real>::infinity()}) {
      test::SplitOscillator system(1, 0);
      auto integrator = makeFirstOrderIntegrator(name);
      integrator->initialise(system, 0, test::vector2(1, 0), 0.1);
      int calls = 0;
      integrator->setStepSizeFunction([&](Real, const Vector&) { return ++calls <= 3 ? 0.1 : bad; });
      for (int i = 0; i < 3; ++i) integrator->step();
      try {
        integrator->step();
        ADD_FAILURE() << name << " accepted a step of " << bad;
      } catch (const InstabilityError& e) {
        const std::string what = e.what();
        EXPECT_EQ(e.step(), 3) << name;
        EXPECT_NEAR(e.time(), 0.3, 1e-12) << name;
        EXPECT_EQ(e.particle(), -1);
        EXPECT_NE(what.find("step 3"), std::string::npos) << what;
        EXPECT_NE(what.find("t = 0.3"), std::string::npos) << what;
        EXPECT_NE(what.find(name), std::string::npos) << what;
      }
      EXPECT_EQ(integrator->stepCount(), 3) << name;  // nothing was stepped
      // advanceTo asks the rule too.
      EXPECT_THROW(integrator->advanceTo(1.0), InstabilityError) << name;
    }
  }
}

TEST(FirstOrderIntegrators, TheRuleSetsEveryStep) {
  // The rule sees (t, y) before each step and its answer is the step taken.
  for (const auto& name : firstOrderIntegratorNames()) {
    test::SplitOscillator system(kOmega, 0);
    auto integrator = makeFirstOrderIntegrator(name);
    integrator->initialise(system, 0, test::vector2(1, 0), 0.01);
    std::vector<Real> answers;
    integrator->setStepSizeFunction([&](Real t, const Vector& y) {
      EXPECT_EQ(t, integrator->time());
      EXPECT_EQ(&y, &integrator->solution());
      answers.push_back(0.002 + 0.001 * std::abs(y[0]) + 0.0001 * answers.size());
      return answers.back();
    });
    Real previous = 0;
    for (int i = 0; i < 10; ++i) {
      integrator->step();
      EXPECT_NEAR(integrator->time() - previous, answers.back(), 1e-15) << name;
      EXPECT_NEAR(integrator->stepSize(), answers.back(), 1e-15) << name;
      previous = integrator->time();
    }
    EXPECT_EQ(answers.size(), 10u);
  }
}

TEST(FirstOrderIntegrators, AdvanceToLandsExactly) {
  for (const auto& name : firstOrderIntegratorNames()) {
    // Fixed step, off the grid: whole steps and a shortened last one.
    test::SplitOscillator system(kOmega, 0);
    auto integrator = makeFirstOrderIntegrator(name);
    integrator->initialise(system, 0, test::vector2(1, 0), 0.01);
    integrator->advanceTo(0.255);
    EXPECT_EQ(integrator->time(), 0.255) << name;
    EXPECT_EQ(integrator->stepCount(), 26) << name;
    EXPECT_NEAR(integrator->stepSize(), 0.005, 1e-12) << name;
    integrator->advanceTo(0.255);  // already there: nothing
    EXPECT_EQ(integrator->stepCount(), 26) << name;
    integrator->step();  // back to the fixed step
    EXPECT_NEAR(integrator->time(), 0.265, 1e-12) << name;
    EXPECT_NEAR(integrator->stepSize(), 0.01, 1e-15) << name;
    EXPECT_THROW(integrator->advanceTo(0.1), InputError) << name;
    // With a rule.
    integrator->setStepSizeFunction([](Real t, const Vector&) { return 0.003 + 0.002 * std::sin(7 * t); });
    for (Real t : {0.5, 0.5 + 1e-3, 0.9, 1.7}) {
      integrator->advanceTo(t);
      EXPECT_EQ(integrator->time(), t) << name;
    }
    const Real tolerance = name == "forward_euler" ? 0.2 : name == "arkode" ? 1e-6 : 2e-3;
    EXPECT_LT((integrator->solution() - system.exact(1.7)).norm() / kOmega, tolerance) << name;
  }
}

TEST(FirstOrderIntegrators, AdvanceToOnTheGridComputesWhatStepsCompute) {
  for (const std::string name : {"forward_euler", "predictor_corrector", "leapfrog"}) {
    test::SplitOscillator a(kOmega, 0.1), b(kOmega, 0.1);
    auto stepped = makeFirstOrderIntegrator(name);
    auto advanced = makeFirstOrderIntegrator(name);
    stepped->initialise(a, 0, test::vector2(1, 0), 0.1);
    advanced->initialise(b, 0, test::vector2(1, 0), 0.1);
    for (int i = 0; i < 10; ++i) stepped->step();
    advanced->advanceTo(1.0);
    EXPECT_EQ(advanced->stepCount(), 10) << name;
    EXPECT_EQ(advanced->time(), 1.0) << name;
    EXPECT_EQ(stepped->solution()[0], advanced->solution()[0]) << name;
    EXPECT_EQ(stepped->solution()[1], advanced->solution()[1]) << name;
  }
}

TEST(ArkodeFirstOrder, AChangingFixedStepIsTheTextbookRk4WithThoseSteps) {
  // setFixedStep between steps: the same as RK4 written out by hand with the same steps, on a
  // nonlinear, time-dependent system. Guards ERKStepSetFixedStep's effect in SUNDIALS 6.4.1.
  Nonlinear system, reference;
  ArkodeFirstOrder integrator;
  integrator.initialise(system, 0, nonlinearStart(), 0.05);
  std::vector<Real> steps;
  integrator.setStepSizeFunction([&](Real t, const Vector&) {
    steps.push_back(0.02 + 0.03 * std::abs(std::sin(5 * t)));
    return steps.back();
  });
  Vector y = nonlinearStart();
  Real t = 0;
  for (int i = 0; i < 20; ++i) {
    integrator.step();
    const Real h = steps.back();
    const Vector k1 = F(reference, t, y), k2 = F(reference, t + h / 2, y + h / 2 * k1),
                 k3 = F(reference, t + h / 2, y + h / 2 * k2), k4 = F(reference, t + h, y + h * k3);
    y += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    t += h;
    EXPECT_LT((integrator.solution() - y).norm(), 1e-13) << "step " << i;
    EXPECT_NEAR(integrator.time(), t, 1e-14);
  }
  EXPECT_EQ(integrator.arkode().options().fixedStep, steps.back());
}

TEST(ArkodeFirstOrder, AdaptiveRunsTakeTheRuleAsAnUpperBound) {
  ArkodeOptions options;
  options.table = "dormand_prince_7_4_5";
  options.adaptive = true;
  options.relativeTolerance = 1e-3;  // loose: ARKODE alone would take long steps
  options.absoluteTolerance = 1e-6;
  test::SplitOscillator system(kOmega, 0);
  ArkodeFirstOrder free(options), bounded(options);
  free.initialise(system, 0, test::vector2(1, 0), 1e-3);
  bounded.initialise(system, 0, test::vector2(1, 0), 1e-3);
  free.advanceTo(1.0);
  const Real bound = 0.004;
  bounded.setStepSizeFunction([&](Real, const Vector&) { return bound; });
  Real previous = 0, largest = 0;
  for (int i = 0; i < 50; ++i) {
    bounded.step();
    largest = std::max(largest, bounded.time() - previous);
    previous = bounded.time();
  }
  bounded.advanceTo(1.0);
  EXPECT_EQ(bounded.time(), 1.0);
  EXPECT_LE(largest, bound * (1 + 1e-12));
  EXPECT_LE(bounded.stepSize(), bound * (1 + 1e-12));
  EXPECT_GT(bounded.stepCount(), 240);
  EXPECT_LT(free.stepCount(), bounded.stepCount() / 2);
  std::printf("dormand_prince rtol 1e-3 to t = 1: %ld steps free, %ld under a bound of %.3f\n", free.stepCount(),
              bounded.stepCount(), bound);
}

TEST(FirstOrderIntegrators, StateViewCarriesYAsDisplacementAndNoVelocity) {
  for (const auto& name : firstOrderIntegratorNames()) {
    test::SplitOscillator system(kOmega, 0);
    auto integrator = makeFirstOrderIntegrator(name);
    integrator->initialise(system, 0.5, test::vector2(1, 0), 0.01);
    StateView before = integrator->state();
    EXPECT_EQ(before.step, 0);
    EXPECT_EQ(before.time, 0.5);
    integrator->step();
    integrator->step();
    const StateView state = integrator->state();
    EXPECT_EQ(state.step, 2) << name;
    EXPECT_EQ(state.time, integrator->time()) << name;
    EXPECT_EQ(&state.displacement, &integrator->solution()) << name;
    EXPECT_EQ(state.displacement.size(), 2) << name;
    EXPECT_EQ(state.velocity.size(), 0) << name;
  }
}

TEST(FirstOrderIntegrators, StabilityMonitorWorksOnAnEmptyVelocity) {
  // A stable run under a TimeLoop: the monitor sees y as the displacement and an empty velocity.
  {
    test::SplitOscillator system(kOmega, 0);
    SplitLeapfrog integrator;
    integrator.initialise(system, 0, test::vector2(1, 0), 0.01);
    StabilityMonitor monitor;
    TimeLoop loop;
    loop.add(monitor);
    const auto stats = loop.run(integrator, 2.0);
    EXPECT_EQ(stats.steps, 200);
  }
  // Forward Euler far beyond its accuracy, w dt = 3: |y| grows by sqrt(10) per step, flipping
  // sign in a few steps; the monitor stops it as grid-scale runaway growth.
  {
    test::SplitOscillator system(kOmega, 0);
    ForwardEuler integrator;
    integrator.initialise(system, 0, test::vector2(1, 0), 3 / kOmega);
    StabilityMonitor monitor;
    TimeLoop loop;
    loop.add(monitor);
    try {
      loop.run(integrator, 1000.0);
      FAIL();
    } catch (const InstabilityError& e) {
      std::printf("forward Euler, w dt = 3: %s\n", e.what());
      EXPECT_LT(e.step(), 100);
      EXPECT_NE(std::string(e.what()).find("displacement"), std::string::npos);
    }
  }
  // A non-finite value in y.
  {
    struct Poisoned : test::SplitOscillator {
      Poisoned() : SplitOscillator(1, 0) {}
      void momentumRate(Real t, Eigen::Ref<const Vector> y, Eigen::Ref<Vector> pdot) override {
        SplitOscillator::momentumRate(t, y, pdot);
        if (t > 0.25) pdot[0] = std::numeric_limits<Real>::quiet_NaN();
      }
    } system;
    ForwardEuler integrator;
    integrator.initialise(system, 0, test::vector2(1, 0), 0.1);
    StabilityMonitor monitor;
    TimeLoop loop;
    loop.add(monitor);
    EXPECT_THROW(loop.run(integrator, 1.0), InstabilityError);
  }
}

}  // namespace
