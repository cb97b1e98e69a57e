// The time step's one home: the step lands on the end time, is never longer than asked, and a run
// too long to be one is refused naming the key.
#include "integrators/TimeStep.hpp"

#include "support/InputErrorKey.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace mfwave {
namespace {

TimeStepRule fraction(Real endTime, Real cfl) {
  TimeStepRule r;
  r.endTime = endTime;
  r.cfl = cfl;
  return r;
}

TEST(TimeStep, AFractionOfTheStableStepIsShortenedToLandOnTheEnd) {
  const TimeStepChoice c = chooseTimeStep(fraction(1.0, 0.5), 0.3);  // 0.15 asked: 7 steps of 1/7
  EXPECT_EQ(c.steps, 7);
  EXPECT_DOUBLE_EQ(c.dt, 1.0 / 7);
  EXPECT_LE(c.dt, 0.15);
  EXPECT_DOUBLE_EQ(c.stableStep, 0.3);
}

TEST(TimeStep, AStepThatDividesTheEndUpToRoundOffIsTakenAsItIs) {
  EXPECT_EQ(chooseTimeStep(fraction(1.0, 1.0), 0.1).steps, 10);  // 1 / 0.1 = 10.000000000000002
  EXPECT_EQ(chooseTimeStep(fraction(0.3, 1.0), 0.1).steps, 3);
}

TEST(TimeStep, AFixedStepIsKept) {
  TimeStepRule r;
  r.endTime = 2.0;
  r.fixedStep = 0.25;
  const TimeStepChoice c = chooseTimeStep(r, 1e-9);  // the stable step plays no part
  EXPECT_EQ(c.steps, 8);
  EXPECT_DOUBLE_EQ(c.dt, 0.25);
}

TEST(TimeStep, AnUnboundedStableStepTakesOneStep) {
  const TimeStepChoice c = chooseTimeStep(fraction(3.0, 0.5), std::numeric_limits<Real>::infinity());
  EXPECT_EQ(c.steps, 1);
  EXPECT_DOUBLE_EQ(c.dt, 3.0);
}

TEST(TimeStep, TooManyStepsAreRefusedNamingTheKey) {
  using testing::inputErrorKey;
  EXPECT_EQ(inputErrorKey([] { chooseTimeStep(fraction(1e300, 0.5), 1.0); }), "integrator.end_time");
  TimeStepRule fixed;
  fixed.endTime = 1e20;
  fixed.fixedStep = 1e-3;
  EXPECT_EQ(inputErrorKey([&] { chooseTimeStep(fixed, 1.0); }), "integrator.time_step");
  EXPECT_EQ(inputErrorKey([] { chooseTimeStep(fraction(1.0, 0.5), -1.0); }), "integrator.cfl");
  EXPECT_EQ(tooManySteps(1e12, "x"), "");
  EXPECT_NE(tooManySteps(1.5e12, "x").find("more than 1e12 is refused"), std::string::npos);
}

TEST(TimeStep, CentralDifferenceLimitIsTwoOverOmegaMax) {
  EXPECT_DOUBLE_EQ(centralDifferenceStableStep(4.0), 0.5);
  EXPECT_EQ(testing::inputErrorKey([] { centralDifferenceStableStep(0.0); }), "omega_max");
  EXPECT_EQ(testing::inputErrorKey([] { centralDifferenceStableStep(std::numeric_limits<Real>::infinity()); }),
            "omega_max");
}

}  // namespace
}  // namespace mfwave
