#include "support/ScriptedIntegrator.hpp"
#include "core/Error.hpp"
#include "observers/TimeLoop.hpp"
#include "observers/ViewAdapter.hpp"

#include <gtest/gtest.h>

#include <vector>

using namespace mfwave;
using mfwave::testing::ScriptedIntegrator;

namespace {

struct ValueLog : Observer {
  std::vector<long> steps;
  std::vector<Real> firstValues;
  bool ended = false;
  void observe(const StateView& s) override {
    steps.push_back(s.step);
    firstValues.push_back(s.displacement[0]);
  }
  void end(const StateView&) override { ended = true; }
};

// Shows 10 x the displacement, and counts how often it formed a view.
struct TenTimes : ViewAdapter {
  long adapted = 0;
  Vector u, v;
  StateView adapt(const StateView& s) override {
    ++adapted;
    u = 10 * s.displacement;
    v = s.velocity;
    return {s.step, s.time, u, v, s.dt};
  }
};

}  // namespace

// Each observer behind one adapter sees exactly the steps it would see in the TimeLoop itself, the
// adapted view, and the view is formed only on steps when someone is due.
TEST(ViewAdapter, KeepsEachObserversIntervalAndFormsTheViewOnlyWhenDue) {
  ScriptedIntegrator integrator(Vector::Constant(1, 1.0), Vector::Zero(1), 0.1,
                                [](long, Vector& u, Vector&) { u[0] += 1; });
  ValueLog third, fourth, direct;
  TenTimes adapter;
  adapter.add(third, 3);
  adapter.add(fourth, 4);
  TimeLoop loop;
  loop.add(adapter);
  loop.add(direct, 3);
  loop.run(integrator, 1.0);
  EXPECT_EQ(third.steps, direct.steps);
  EXPECT_EQ(third.steps, (std::vector<long>{0, 3, 6, 9, 10}));
  EXPECT_EQ(fourth.steps, (std::vector<long>{0, 4, 8, 10}));
  EXPECT_TRUE(third.ended && fourth.ended);
  ASSERT_EQ(third.firstValues.size(), direct.firstValues.size());
  for (std::size_t k = 0; k < third.firstValues.size(); ++k)
    EXPECT_DOUBLE_EQ(third.firstValues[k], 10 * direct.firstValues[k]);
  // Views formed: begin, steps 3, 4, 6, 8, 9 and the end (step 10 is nobody's multiple).
  EXPECT_EQ(adapter.adapted, 7);
}

TEST(ViewAdapter, RejectsZeroInterval) {
  ValueLog log;
  TenTimes adapter;
  EXPECT_THROW(adapter.add(log, 0), InputError);
}
