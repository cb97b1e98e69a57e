#include "support/ScriptedIntegrator.hpp"
#include "core/Error.hpp"
#include "core/Interruption.hpp"
#include "observers/TimeLoop.hpp"

#include <gtest/gtest.h>

#include <csignal>
#include <vector>

using namespace mfwave;
using mfwave::testing::ScriptedIntegrator;

namespace {
struct StepLog : Observer {
  std::vector<long> steps;
  bool ended = false;
  void observe(const StateView& s) override { steps.push_back(s.step); }
  void end(const StateView&) override { ended = true; }
};
}  // namespace

TEST(TimeLoop, ObserversSeeEveryNthStepAndTheLast) {
  ScriptedIntegrator integrator(Vector::Zero(2), Vector::Zero(2), 0.1, [](long, Vector&, Vector&) {});
  StepLog everyStep, everyThird;
  TimeLoop loop;
  loop.add(everyStep, 1);
  loop.add(everyThird, 3);
  const RunStatistics stats = loop.run(integrator, 1.0);
  EXPECT_EQ(stats.steps, 10);
  EXPECT_NEAR(stats.endTime, 1.0, 1e-12);
  EXPECT_EQ(everyStep.steps.size(), 11u);  // initial state + 10 steps
  EXPECT_EQ(everyThird.steps, (std::vector<long>{0, 3, 6, 9, 10}));
  EXPECT_TRUE(everyThird.ended);
}

TEST(TimeLoop, RejectsZeroInterval) {
  StepLog log;
  TimeLoop loop;
  EXPECT_THROW(loop.add(log, 0), InputError);
}

// SIGINT or SIGTERM while the loop steps (core/Interruption): the loop ends after the step it is in,
// every observer sees that step and ends, the statistics say where; a real signal is caught only
// while a loop runs, and the first one restores the default action.
TEST(TimeLoop, AnInterruptionEndsTheLoopAfterTheCurrentStep) {
  clearInterruption();
  ScriptedIntegrator integrator(Vector::Zero(2), Vector::Zero(2), 0.1, [](long step, Vector&, Vector&) {
    if (step == 4) std::raise(SIGTERM);  // as a scheduler would, in the middle of the run
  });
  StepLog everyStep, everyThird;
  TimeLoop loop;
  loop.add(everyStep, 1);
  loop.add(everyThird, 3);
  const RunStatistics stats = loop.run(integrator, 1.0);
  EXPECT_TRUE(stats.interrupted);
  EXPECT_EQ(interruptionSignal(), SIGTERM);
  EXPECT_STREQ(interruptionSignalName(), "SIGTERM");
  EXPECT_EQ(stats.steps, 4);
  EXPECT_NEAR(stats.endTime, 0.4, 1e-12);
  EXPECT_EQ(everyThird.steps, (std::vector<long>{0, 3, 4}));  // the last step taken is observed
  EXPECT_TRUE(everyStep.ended && everyThird.ended);
  // Outside a loop the default action is back: no handler of ours is installed.
  struct sigaction now {};
  sigaction(SIGTERM, nullptr, &now);
  EXPECT_EQ(now.sa_handler, SIG_DFL);

  // While the flag is up, a new loop takes no step; cleared, it runs to its end.
  ScriptedIntegrator quiet(Vector::Zero(2), Vector::Zero(2), 0.1, [](long, Vector&, Vector&) {});
  EXPECT_EQ(TimeLoop().run(quiet, 1.0).steps, 0);
  clearInterruption();
  const RunStatistics full = TimeLoop().run(quiet, 1.0);
  EXPECT_EQ(full.steps, 10);
  EXPECT_FALSE(full.interrupted);
}

// On ranks (TimeLoop::agreeAcrossRanks): the loop asks the agreement at every step boundary with
// its own signal and wall-clock flag, and obeys what the ranks agreed. Here a stand-in for the
// other ranks reports a SIGTERM this process never received, at the fifth boundary: the loop stops
// after step 4 as if the signal were its own, and raises the flag so the study stops too.
TEST(TimeLoop, AnAgreedStopEndsEveryRanksLoopAfterTheSameStep) {
  clearInterruption();
  ScriptedIntegrator integrator(Vector::Zero(2), Vector::Zero(2), 0.1, [](long, Vector&, Vector&) {});
  StepLog log;
  TimeLoop loop;
  loop.add(log, 3);
  int boundaries = 0;
  loop.agreeAcrossRanks([&boundaries](int* values, int count) {
    ASSERT_EQ(count, 2);
    EXPECT_EQ(values[0], 0);  // this process's own signal: none
    EXPECT_EQ(values[1], 0);  // no store, so no wall-clock checkpoint
    if (++boundaries == 5) values[0] = SIGTERM;  // another rank's
  });
  const RunStatistics stats = loop.run(integrator, 1.0);
  EXPECT_EQ(boundaries, 5);
  EXPECT_EQ(stats.steps, 4);
  EXPECT_TRUE(stats.interrupted);
  EXPECT_EQ(interruptionSignal(), SIGTERM);
  EXPECT_EQ(log.steps, (std::vector<long>{0, 3, 4}));
  clearInterruption();
}
