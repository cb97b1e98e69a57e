#include "support/ScriptedIntegrator.hpp"
#include "core/Error.hpp"
#include "observers/TimeLoop.hpp"

#include <gtest/gtest.h>

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
