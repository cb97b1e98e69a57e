#include "support/ScriptedIntegrator.hpp"
#include "core/Error.hpp"
#include "observers/StabilityMonitor.hpp"
#include "observers/TimeLoop.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <limits>
#include <string>
#include <utility>

using namespace mfwave;
using mfwave::testing::ScriptedIntegrator;

TEST(StabilityMonitor, StopsAtTheFirstNonFiniteValueAndNamesParticleStepAndTime) {
  // 3 components per particle; dof 7 is particle 2, component 1.
  ScriptedIntegrator integrator(Vector::Ones(9), Vector::Zero(9), 0.5, [](long step, Vector& u, Vector&) {
    if (step == 4) u[7] = std::numeric_limits<Real>::quiet_NaN();
  });
  StabilityMonitorOptions options;
  options.components = 3;
  StabilityMonitor monitor(options);
  TimeLoop loop;
  loop.add(monitor);
  try {
    loop.run(integrator, 10.0);
    FAIL() << "the NaN was not caught";
  } catch (const InstabilityError& e) {
    EXPECT_EQ(e.step(), 4);
    EXPECT_DOUBLE_EQ(e.time(), 2.0);
    EXPECT_EQ(e.particle(), 2);
    const std::string message = e.what();
    EXPECT_NE(message.find("non-finite"), std::string::npos) << message;
    EXPECT_NE(message.find("particle 2"), std::string::npos) << message;
    EXPECT_NE(message.find("component 1"), std::string::npos) << message;
  }
  EXPECT_EQ(integrator.stepCount(), 4);  // stopped at once
}

TEST(StabilityMonitor, CatchesASignFlippingModeSoonAfterItExceedsTheFactor) {
  // The mode that escapes central difference just above its limit: u_k = -1.3 u_{k-1}.
  ScriptedIntegrator integrator(Vector::Constant(4, 1.0), Vector::Zero(4), 1.0,
                                [](long, Vector& u, Vector&) { u *= -1.3; });
  StabilityMonitorOptions options;
  options.growthFactor = 1e3;
  options.window = 30;
  StabilityMonitor monitor(options);
  TimeLoop loop;
  loop.add(monitor);
  try {
    loop.run(integrator, 1000.0);
    FAIL() << "not caught";
  } catch (const InstabilityError& e) {
    EXPECT_NE(std::string(e.what()).find("grid-scale"), std::string::npos) << e.what();
  }
  // At step 31 the reference is the amplitude at step 0 and 1.3^31 = 3.4e3 > 1e3: caught there.
  EXPECT_EQ(integrator.stepCount(), 31);
  // r = |-1.3 - 2 - 1/1.3| = 4.07 for this mode.
  EXPECT_NEAR(monitor.oscillationRatio(), 1.3 + 2 + 1 / 1.3, 1e-12);
}

TEST(StabilityMonitor, SmoothGrowthFromRestIsNotAnInstability) {
  // The onset of a Ricker source, exp(-(pi f (t - t0))^2) with f = 4, t0 = 0.3, sampled at dt =
  // 0.008: grows a million-fold within 40 steps, but smoothly (r ~ (omega dt)^2 << 1).
  ScriptedIntegrator integrator(Vector::Zero(3), Vector::Zero(3), 0.008, [](long step, Vector& u, Vector& v) {
    const Real t = 0.008 * static_cast<Real>(step);
    const Real a = std::pow(M_PI * 4 * (t - 0.3), 2);
    u[1] = (1 - 2 * a) * std::exp(-a);
    v[1] = u[1];
  });
  StabilityMonitorOptions options;
  options.window = 20;
  StabilityMonitor monitor(options);
  TimeLoop loop;
  loop.add(monitor);
  EXPECT_NO_THROW(loop.run(integrator, 1.5));
  EXPECT_EQ(integrator.stepCount(), 187);  // 1.5 / 0.008 = 187.5: the loop stops within half a step
}

TEST(StabilityMonitor, SmoothGeometricGrowthIsLeftToTheAbsoluteLimit) {
  // u_k = 1.3 u_{k-1} without sign flips is not grid-scale: by design the growth test ignores it.
  ScriptedIntegrator integrator(Vector::Constant(1, 1.0), Vector::Zero(1), 1.0,
                                [](long, Vector& u, Vector&) { u *= 1.3; });
  StabilityMonitor monitor;
  TimeLoop loop;
  loop.add(monitor);
  EXPECT_NO_THROW(loop.run(integrator, 100.0));
}

TEST(StabilityMonitor, LetsABoundedOscillationAndAResponseFromRestRun) {
  // From rest, growing quickly to a bounded oscillation: no false alarm.
  ScriptedIntegrator integrator(Vector::Zero(2), Vector::Zero(2), 0.01, [](long step, Vector& u, Vector& v) {
    const Real t = 0.01 * static_cast<Real>(step);
    u[0] = (1 - std::exp(-t)) * std::sin(40 * t) * 1e-3;
    u[1] = 1e-12 * t;
    v[0] = std::cos(40 * t);
  });
  StabilityMonitor monitor;
  TimeLoop loop;
  loop.add(monitor);
  EXPECT_NO_THROW(loop.run(integrator, 20.0));
}

TEST(StabilityMonitor, AbsoluteLimitStopsSlowGrowth) {
  ScriptedIntegrator integrator(Vector::Constant(1, 1.0), Vector::Zero(1), 1.0,
                                [](long, Vector& u, Vector&) { u *= 1.001; });
  StabilityMonitorOptions options;
  options.absoluteLimit = 2.0;
  StabilityMonitor monitor(options);
  TimeLoop loop;
  loop.add(monitor);
  EXPECT_THROW(loop.run(integrator, 1e4), InstabilityError);
  EXPECT_EQ(integrator.stepCount(), 694);  // first k with 1.001^k > 2
}

TEST(StabilityMonitor, RejectsMeaninglessOptions) {
  StabilityMonitorOptions options;
  options.growthFactor = 0.5;
  EXPECT_THROW(StabilityMonitor{options}, InputError);
}

namespace {

// A mode u = e^{s t}, v = s e^{s t} (omega^2 = -s^2 < 0), sampled every dt: smooth, never grid-scale.
ScriptedIntegrator slowlyGrowingMode(Real s, Real dt) {
  return ScriptedIntegrator(Vector::Constant(2, 1.0), Vector::Constant(2, s), dt,
                            [s, dt](long step, Vector& u, Vector& v) {
                              u.setConstant(std::exp(s * dt * static_cast<Real>(step)));
                              v = s * u;
                            });
}

}  // namespace

TEST(StabilityMonitor, SlowGrowthAfterTheLoadsEndedIsStopped) {
  // s = 0.01 per unit time, dt = 0.1: a thousandth per step, r ~ 1e-6. While loads act (before
  // quietAfter = 100, step 1000) it is left alone; the quiet reference is the largest amplitude up
  // to the 50th observation from then (step 1049, e^{1.049}), and the run stops at the first step
  // with e^{0.001 k} > 1e3 e^{1.049}: k > 1049 + 1000 ln 1000 = 7956.8, step 7957.
  ScriptedIntegrator integrator = slowlyGrowingMode(0.01, 0.1);
  StabilityMonitorOptions options;
  options.quietAfter = 100;
  StabilityMonitor monitor(options);
  TimeLoop loop;
  loop.add(monitor);
  try {
    loop.run(integrator, 2000.0);
    FAIL() << "slow growth after the loads was not caught";
  } catch (const InstabilityError& e) {
    EXPECT_NE(std::string(e.what()).find("growth after the loads ended"), std::string::npos) << e.what();
    EXPECT_EQ(e.step(), 7957);
  }
  // Without an end of the loads the same run is left to the absolute limit (and ends normally).
  ScriptedIntegrator forced = slowlyGrowingMode(0.01, 0.1);
  StabilityMonitor watching;
  TimeLoop second;
  second.add(watching);
  EXPECT_NO_THROW(second.run(forced, 2000.0));
}

TEST(StabilityMonitor, FreeMotionAfterTheLoadsIsNotGrowth) {
  // Free vibration, quiet from t = 0, 10^6 steps per period, so that the quiet reference is taken
  // while one field is still near zero. Set moving (u = sin t, v = cos t): u grows 3000-fold
  // against its reference (sin(50 dt)), v does not. Released from a displacement (u = cos t, v = -sin t): the
  // other way round. A body translating at v0 (u = v0 t): u grows without bound, v is constant.
  const Real dt = 2 * M_PI / 1e6;
  const auto run = [dt](ScriptedIntegrator integrator, Real endTime) {
    StabilityMonitorOptions options;
    options.quietAfter = 0;
    StabilityMonitor monitor(options);
    TimeLoop loop;
    loop.add(monitor);
    EXPECT_NO_THROW(loop.run(integrator, endTime));
  };
  run(ScriptedIntegrator(Vector::Zero(1), Vector::Ones(1), dt,
                         [dt](long k, Vector& u, Vector& v) {
                           u[0] = std::sin(dt * static_cast<Real>(k));
                           v[0] = std::cos(dt * static_cast<Real>(k));
                         }),
      2 * M_PI);
  run(ScriptedIntegrator(Vector::Ones(1), Vector::Zero(1), dt,
                         [dt](long k, Vector& u, Vector& v) {
                           u[0] = std::cos(dt * static_cast<Real>(k));
                           v[0] = -std::sin(dt * static_cast<Real>(k));
                         }),
      2 * M_PI);
  run(ScriptedIntegrator(Vector::Zero(1), Vector::Constant(1, 2.0), dt,
                         [dt](long k, Vector& u, Vector& v) {
                           u[0] = 2 * dt * static_cast<Real>(k);
                           v[0] = 2;
                         }),
      2 * M_PI);
}

TEST(StabilityMonitor, ScansABigStateInParallelAndNamesTheSameEntryOnAnyThreadCount) {
  // 10^6 unknowns scan in blocks on both threads; the answer must be that of one pass in index
  // order: the first non-finite entry (a later one and a larger value before it notwithstanding),
  // and, when all are finite, the first entry of the largest magnitude.
  const Index n = 1000000;
  auto firstFailure = [&](int threads, bool withNaN) {
    Vector u = Vector::Constant(n, 0.5);
    u[12345] = 5;    // largest, first
    u[876543] = -5;  // as large, later: not the one named
    ScriptedIntegrator integrator(u, Vector::Zero(n), 0.5, [&](long step, Vector& state, Vector&) {
      if (step != 2) return;
      if (withNaN) {
        state[700001] = std::numeric_limits<Real>::infinity();
        state[900000] = std::numeric_limits<Real>::quiet_NaN();
      } else {
        state *= 1e9;  // above the absolute limit
      }
    });
    StabilityMonitorOptions options;
    options.components = 1;
    options.absoluteLimit = 1e6;
    StabilityMonitor monitor(options);
    TimeLoop loop;
    loop.add(monitor);
    const int before = omp_get_max_threads();
    omp_set_num_threads(threads);
    std::string message;
    long particle = -1;
    try {
      loop.run(integrator, 10.0);
    } catch (const InstabilityError& e) {
      message = e.what();
      particle = e.particle();
    }
    omp_set_num_threads(before);
    return std::make_pair(particle, message);
  };
  for (bool withNaN : {true, false}) {
    const auto one = firstFailure(1, withNaN), two = firstFailure(2, withNaN);
    EXPECT_EQ(one.first, withNaN ? 700001 : 12345) << one.second;
    EXPECT_EQ(one, two);
  }
}
