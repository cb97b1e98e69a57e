// Measured orders, stability and energy behaviour of the first-order integrators
// (forward Euler, predictor-corrector, split leapfrog, ARKODE RK4).

#include "FirstOrderTestSystems.hpp"
#include "integrators/ArkodeFirstOrder.hpp"
#include "integrators/FirstOrderIntegratorFactory.hpp"
#include "integrators/ForwardEuler.hpp"
#include "integrators/PredictorCorrector.hpp"
#include "integrators/SplitLeapfrog.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

using namespace mfwave;

namespace {

constexpr Real kConvergenceOmega = 2 * M_PI;  // period 1

struct Case {
  std::string name;  // factory name
  Real order;
  int coarsestSteps;          // oscillator: steps over the interval on the coarsest of four grids
  int pendulumCoarsestSteps;  // pendulum: the same, of five grids
  int ruleCoarsestSteps;      // pendulum with a step rule: end time / h on the coarsest of five grids
};

std::string joined(const std::vector<Real>& values) {
  std::string line;
  for (Real v : values) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, " %.4g", v);
    line += buffer;
  }
  return line;
}

// Fixed steps from y0 at t = 0 to endTime.
Vector solve(const std::string& name, FirstOrderSystem& system, const Vector& y0, Real endTime, int steps) {
  auto integrator = makeFirstOrderIntegrator(name);
  integrator->initialise(system, 0, y0, endTime / steps);
  for (int i = 0; i < steps; ++i) integrator->step();
  EXPECT_NEAR(integrator->time(), endTime, 1e-12 * endTime) << name;
  return integrator->solution();
}

std::vector<Real> ratesFromErrors(const std::vector<Real>& errors) {
  std::vector<Real> rates;
  for (size_t i = 1; i < errors.size(); ++i) rates.push_back(std::log2(errors[i - 1] / errors[i]));
  return rates;
}

// Errors against the exact solution on four grids, each half the step of the previous.
std::vector<Real> oscillatorRates(const Case& c, Real zeta) {
  const Real endTime = 2;
  test::SplitOscillator system(kConvergenceOmega, zeta);
  const Vector exact = system.exact(endTime);
  std::vector<Real> errors;
  for (int level = 0; level < 4; ++level) {
    const Vector y = solve(c.name, system, test::vector2(1, 0), endTime, c.coarsestSteps << level);
    errors.push_back(std::max(std::abs(y[0] - exact[0]), std::abs(y[1] - exact[1]) / kConvergenceOmega));
  }
  const auto rates = ratesFromErrors(errors);
  std::printf("%-20s oscillator zeta %.2f: errors%s; rates%s\n", c.name.c_str(), zeta, joined(errors).c_str(),
              joined(rates).c_str());
  return rates;
}

// Self-convergence on a nonlinear problem: differences between solutions on five grids.
template <class Solver>
std::vector<Real> selfConvergenceRates(const std::string& label, Solver solveWith, int coarsest) {
  std::vector<Vector> solutions;
  for (int level = 0; level < 5; ++level) solutions.push_back(solveWith(coarsest << level));
  std::vector<Real> differences;
  for (size_t i = 1; i < solutions.size(); ++i) differences.push_back((solutions[i] - solutions[i - 1]).norm());
  const auto rates = ratesFromErrors(differences);
  std::printf("%-20s %s: differences%s; rates%s\n", label.c_str(), "self-convergence", joined(differences).c_str(),
              joined(rates).c_str());
  return rates;
}

const std::vector<Case>& cases() {
  static const std::vector<Case> list{
      {"forward_euler", 1, 10000, 5000, 5000},
      {"predictor_corrector", 2, 100, 200, 200},
      {"leapfrog", 2, 100, 50, 100},
      {"arkode", 4, 50, 60, 200},  // classic_rk4, the default table
  };
  return list;
}

TEST(FirstOrderConvergence, OscillatorOrders) {
  for (const auto& c : cases())
    for (Real rate : oscillatorRates(c, 0)) EXPECT_NEAR(rate, c.order, 0.1) << c.name;
}

TEST(FirstOrderConvergence, DampedOscillatorOrders) {
  // P depends on p: the leapfrog's predictor p* keeps it second order.
  for (const auto& c : cases())
    for (Real rate : oscillatorRates(c, 0.1)) EXPECT_NEAR(rate, c.order, 0.1) << c.name;
}

TEST(FirstOrderConvergence, ForcedPendulumOrders) {
  const Real endTime = 4;
  for (const auto& c : cases()) {
    test::ForcedPendulum system(0.2, 0.5);
    const auto rates = selfConvergenceRates(
        c.name + " pendulum",
        [&](int steps) { return solve(c.name, system, test::vector2(2.0, 0.0), endTime, steps); },
        c.pendulumCoarsestSteps);
    for (Real rate : rates) EXPECT_NEAR(rate, c.order, 0.1) << c.name;
  }
}

TEST(FirstOrderConvergence, OrdersHoldWithAStateDependentStepRule) {
  // dt = h (0.6 + 0.4 cos q): the step varies smoothly with the state, between 0.43 h and h on
  // this pendulum; advanceTo shortens the last step to land on the end time. The leapfrog's
  // kicks use each step's own dt with the P_n of the previous step.
  const Real endTime = 4;
  for (const auto& c : cases()) {
    test::ForcedPendulum system(0.2, 0.5);
    long steps = 0;
    const auto rates = selfConvergenceRates(
        c.name + " pendulum, rule",
        [&](int n) {
          const Real h = endTime / n;
          auto integrator = makeFirstOrderIntegrator(c.name);
          integrator->initialise(system, 0, test::vector2(2.0, 0.0), h);
          integrator->setStepSizeFunction([h](Real, const Vector& y) { return h * (0.6 + 0.4 * std::cos(y[0])); });
          integrator->advanceTo(endTime);
          EXPECT_EQ(integrator->time(), endTime);
          steps = integrator->stepCount();
          return integrator->solution();
        },
        c.ruleCoarsestSteps);
    std::printf("  finest grid: %ld steps against %d fixed ones\n", steps, c.ruleCoarsestSteps << 4);
    EXPECT_GT(steps, 1.3 * (c.ruleCoarsestSteps << 4));  // the rule really shortened the steps
    for (Real rate : rates) EXPECT_NEAR(rate, c.order, 0.1) << c.name;
  }
}

TEST(FirstOrderConvergence, LeapfrogStaysSecondOrderUnderAbruptStepChanges) {
  // Steps cycling h, 0.4 h, 1.7 h (ratios 0.4 and 4.25 between neighbours) on the damped
  // oscillator, whose P depends on p: P_n, computed with the previous step's predictor, is
  // reused by a kick of a different length, and the scheme stays second order.
  const Real endTime = 2;
  test::SplitOscillator reference(kConvergenceOmega, 0.1);
  const Vector exact = reference.exact(endTime);
  std::vector<Real> errors;
  for (int level = 0; level < 4; ++level) {
    const Real h = endTime / (60 << level);
    test::SplitOscillator system(kConvergenceOmega, 0.1);
    SplitLeapfrog integrator;
    integrator.initialise(system, 0, test::vector2(1, 0), h);
    const Real factors[] = {1.0, 0.4, 1.7};
    integrator.setStepSizeFunction([&](Real, const Vector&) { return h * factors[integrator.stepCount() % 3]; });
    integrator.advanceTo(endTime);
    const Vector& y = integrator.solution();
    errors.push_back(std::max(std::abs(y[0] - exact[0]), std::abs(y[1] - exact[1]) / kConvergenceOmega));
  }
  const auto rates = ratesFromErrors(errors);
  std::printf("leapfrog, steps h, 0.4h, 1.7h, damped oscillator: errors%s; rates%s\n", joined(errors).c_str(),
              joined(rates).c_str());
  for (Real rate : rates) EXPECT_NEAR(rate, 2, 0.1);
}

TEST(FirstOrderConvergence, LeapfrogStaysSecondOrderWhenTheDriftDependsOnTheConfiguration) {
  // q' = p - c q^2: a drift with Q(q_n, p_{n+1/2}) would miss dt^2/2 (dQ/dq) Q per step (first
  // order); the leapfrog evaluates Q at the extrapolated midpoint q* = q_n + dt/2 Q_{n-1/2}
  // (SplitLeapfrog.hpp) and stays second order, like the predictor-corrector.
  const Real endTime = 2;
  for (const auto& [name, order] : std::vector<std::pair<std::string, Real>>{{"leapfrog", 2}, {"predictor_corrector", 2}}) {
    test::SelfCoupledDrift system(0.5);
    const auto rates = selfConvergenceRates(
        name + " q-dependent Q",
        [&](int steps) { return solve(name, system, test::vector2(1.0, 0.0), endTime, steps); }, 400);
    for (Real rate : rates) EXPECT_NEAR(rate, order, 0.1) << name;
  }
}

TEST(FirstOrderConvergence, LeapfrogEnergyIsBoundedWithoutDrift) {
  // Undamped oscillator, w dt = 0.1, 10^5 steps (about 1600 periods). Stormer-Verlet conserves
  // the shadow energy v^2 + w^2 (1 - (w dt / 2)^2) x^2 exactly (up to round-off), so the energy
  // error stays in a band of relative width (w dt)^2 / 4 and does not drift.
  const Real wdt = 0.1;
  test::SplitOscillator system(kConvergenceOmega, 0);
  SplitLeapfrog integrator;
  const Vector y0 = test::vector2(1, 0);
  integrator.initialise(system, 0, y0, wdt / kConvergenceOmega);
  const Real e0 = system.energy(y0);
  const Real x = wdt * wdt / 4;
  auto shadow = [&](const Vector& y) { return y[1] * y[1] + kConvergenceOmega * kConvergenceOmega * (1 - x) * y[0] * y[0]; };
  const Real shadow0 = shadow(y0);
  const int steps = 100000;
  Real maxFirst = 0, maxLast = 0, maxAll = 0, shadowMid = 0, maxShadowError = 0;
  for (int i = 1; i <= steps; ++i) {
    integrator.step();
    const Vector& y = integrator.solution();
    const Real error = std::abs(system.energy(y) - e0) / e0;
    maxAll = std::max(maxAll, error);
    if (i <= 1000) maxFirst = std::max(maxFirst, error);
    if (i > steps - 1000) maxLast = std::max(maxLast, error);
    maxShadowError = std::max(maxShadowError, std::abs(shadow(y) - shadow0) / shadow0);
    if (i == steps / 2) shadowMid = shadow(y);
  }
  const Real drift = std::abs(shadow(integrator.solution()) - shadowMid) / shadow0;
  std::printf("split leapfrog, w dt = %.2f, %d steps: energy error band first %.6e last %.6e all %.6e (bound %.6e); "
              "shadow energy: max error %.3e, drift over the last half %.3e\n",
              wdt, steps, maxFirst, maxLast, maxAll, wdt * wdt / 4, maxShadowError, drift);
  EXPECT_LE(maxAll, 1.01 * wdt * wdt / 4);
  EXPECT_GT(maxFirst, 0.5 * wdt * wdt / 4);  // the band is really there
  EXPECT_NEAR(maxLast, maxFirst, 1e-3 * maxFirst);
  EXPECT_LT(maxShadowError, 1e-11);
  EXPECT_LT(drift, 1e-11);
  EXPECT_EQ(integrator.stepCount(), steps);
  EXPECT_NEAR(integrator.time(), steps * wdt / kConvergenceOmega, 1e-9);
}

TEST(FirstOrderConvergence, LeapfrogWithAStateDependentStepLosesEnergyConservation) {
  // Not a requirement but a property to know: with dt = (0.1 / w)(0.75 + 0.25 x) the step map is
  // no longer symplectic and the energy drifts (here downwards) instead of staying in a band.
  test::SplitOscillator system(kConvergenceOmega, 0);
  SplitLeapfrog integrator;
  const Vector y0 = test::vector2(1, 0);
  integrator.initialise(system, 0, y0, 0.1 / kConvergenceOmega);
  integrator.setStepSizeFunction([](Real, const Vector& y) { return (0.1 / kConvergenceOmega) * (0.75 + 0.25 * y[0]); });
  const Real e0 = system.energy(y0);
  const int steps = 100000, window = 10000;
  Real meanFirst = 0, meanLast = 0;
  for (int i = 1; i <= steps; ++i) {
    integrator.step();
    const Real error = (system.energy(integrator.solution()) - e0) / e0;
    if (i <= window) meanFirst += error / window;
    if (i > steps - window) meanLast += error / window;
  }
  std::printf("split leapfrog, state-dependent step, %d steps to t = %.0f: mean relative energy error %.3e over "
              "the first %d steps, %.3e over the last\n",
              steps, integrator.time(), meanFirst, window, meanLast);
  EXPECT_LT(meanLast, 5 * meanFirst);  // both negative: a drift, ten times the early level
}

// |y_n| with y scaled to [w x; v] after n steps of w dt from (1, 0).
Real scaledAmplitude(const std::string& name, Real wdt, int steps) {
  test::SplitOscillator system(kConvergenceOmega, 0);
  auto integrator = makeFirstOrderIntegrator(name);
  integrator->initialise(system, 0, test::vector2(1, 0), wdt / kConvergenceOmega);
  for (int i = 0; i < steps; ++i) integrator->step();
  const Vector& y = integrator->solution();
  return std::hypot(kConvergenceOmega * y[0], y[1]) / kConvergenceOmega;
}

TEST(FirstOrderConvergence, AmplificationOfAnUndampedOscillation) {
  // Per step, |y| grows by |R(i w dt)| exactly (the scaled amplification matrix is normal):
  // forward Euler sqrt(1 + h^2), the midpoint predictor-corrector sqrt(1 + h^4 / 4), RK4
  // sqrt(1 - h^6 / 72 + h^8 / 576), with h = w dt. The split leapfrog is not normal in these
  // variables but its eigenvalues have modulus 1 for h < 2: bounded, no growth.
  const Real h = 0.1;
  const int steps = 1000;
  const Real euler = scaledAmplitude("forward_euler", h, steps);
  const Real pc = scaledAmplitude("predictor_corrector", h, steps);
  const Real rk4 = scaledAmplitude("arkode", h, steps);
  const Real leapfrog = scaledAmplitude("leapfrog", h, steps);
  const Real eulerExpected = std::pow(1 + h * h, steps / 2.0);
  const Real pcExpected = std::pow(1 + std::pow(h, 4) / 4, steps / 2.0);
  const Real rk4Expected = std::pow(1 - std::pow(h, 6) / 72 + std::pow(h, 8) / 576, steps / 2.0);
  std::printf("amplitude after %d steps of w dt = %.2f: forward Euler %.6f (expected %.6f), predictor-corrector "
              "%.9f (%.9f), RK4 %.12f (%.12f), leapfrog %.6f\n",
              steps, h, euler, eulerExpected, pc, pcExpected, rk4, rk4Expected, leapfrog);
  EXPECT_NEAR(euler / eulerExpected, 1, 1e-12);
  EXPECT_NEAR(pc / pcExpected, 1, 1e-12);
  EXPECT_NEAR(rk4 / rk4Expected, 1, 1e-12);
  EXPECT_GT(euler, 140);  // e^{n h^2 / 2} = e^5: forward Euler is unstable for every dt
  EXPECT_GT(pc, 1.012);   // weakly unstable
  EXPECT_LT(rk4, 1);      // slightly dissipative
  EXPECT_LT(leapfrog, 1.06);
  EXPECT_GT(leapfrog, 0.94);
  // Just below and above the leapfrog's limit w dt = 2.
  EXPECT_LT(scaledAmplitude("leapfrog", 1.98, 10000), 10);
  EXPECT_GT(scaledAmplitude("leapfrog", 2.02, 300), 1e3);
}

}  // namespace
