#include "core/Error.hpp"
#include "core/TimeFunction.hpp"
#include "support/InputErrorKey.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

using namespace mfwave;
using mfwave::testing::inputErrorKey;

TEST(TimeFunction, TrianglePulseOfDingLongWuEq36) {
  const TimeFunction f = TimeFunction::triangle(0, 1, 1, 1);
  EXPECT_DOUBLE_EQ(f(-0.5), 0);
  EXPECT_DOUBLE_EQ(f(0.25), 0.25);
  EXPECT_DOUBLE_EQ(f(1.0), 1.0);
  EXPECT_DOUBLE_EQ(f(1.5), 0.5);
  EXPECT_DOUBLE_EQ(f(2.0), 0);
  EXPECT_DOUBLE_EQ(f(7.0), 0);
}

TEST(TimeFunction, RampAndConstant) {
  const TimeFunction ramp = TimeFunction::ramp(1, 2, 4);
  EXPECT_DOUBLE_EQ(ramp(0.5), 0);
  EXPECT_DOUBLE_EQ(ramp(2.0), 2);
  EXPECT_DOUBLE_EQ(ramp(10), 4);
  EXPECT_DOUBLE_EQ(TimeFunction::constant(-3)(123), -3);
}

TEST(TimeFunction, RickerWaveletPeakZerosAndZeroMean) {
  // Peak at the delay, zeros at t0 +- 1 / (sqrt(2) pi f), zero mean (its spectrum vanishes at 0).
  const Real f = 5, t0 = 0.4;
  const TimeFunction ricker = TimeFunction::ricker(f, t0, 2);
  EXPECT_DOUBLE_EQ(ricker(t0), 2);
  EXPECT_NEAR(ricker(t0 + 1 / (std::sqrt(2.0) * M_PI * f)), 0, 1e-14);
  Real integral = 0;
  const Real dt = 1e-4;
  for (Real t = t0 - 1; t <= t0 + 1; t += dt) integral += ricker(t) * dt;
  EXPECT_NEAR(integral, 0, 1e-10);
}

TEST(TimeFunction, TabulatedInterpolatesAndHoldsTheEnds) {
  const TimeFunction table = TimeFunction::tabulated({0, 1, 3}, {0, 2, -2});
  EXPECT_DOUBLE_EQ(table(-1), 0);
  EXPECT_DOUBLE_EQ(table(0.5), 1);
  EXPECT_DOUBLE_EQ(table(2), 0);
  EXPECT_DOUBLE_EQ(table(5), -2);
}

TEST(TimeFunction, TabulatedFromCsvWithHeaderAndComments) {
  const auto path = std::filesystem::temp_directory_path() / "mfwave-time-function.csv";
  {
    std::ofstream out(path);
    out << "time [s],force [N]\n# rising\n0,0\n1,10\n\n2,0\n";
  }
  const TimeFunction f = TimeFunction::fromCsv(path.string());
  EXPECT_DOUBLE_EQ(f(0.5), 5);
  EXPECT_DOUBLE_EQ(f(1.5), 5);
  EXPECT_NE(f.describe().find("3 points"), std::string::npos);
}

TEST(TimeFunction, BadInputNamesTheParameter) {
  EXPECT_EQ(inputErrorKey([] { TimeFunction::ramp(0, 0); }), "duration");
  EXPECT_EQ(inputErrorKey([] { TimeFunction::triangle(0, 1, -1); }), "fall");
  EXPECT_EQ(inputErrorKey([] { TimeFunction::ricker(0, 1); }), "peak_frequency");
  EXPECT_EQ(inputErrorKey([] { TimeFunction::tabulated({0, 0}, {1, 2}); }), "times[1]");
  EXPECT_EQ(inputErrorKey([] { TimeFunction::tabulated({0, 1}, {1}); }), "values");
  EXPECT_EQ(inputErrorKey([] { TimeFunction::fromCsv("/nonexistent/table.csv"); }), "file");
  const auto path = std::filesystem::temp_directory_path() / "mfwave-bad-table.csv";
  {
    std::ofstream out(path);
    out << "t,v\n0,1\n1,x\n";
  }
  try {
    TimeFunction::fromCsv(path.string());
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("line 3"), std::string::npos) << e.what();
  }
}

TEST(TimeFunction, PiecewiseLinearBreakpointsReproduceTheFunction) {
  std::vector<Real> times, values;
  for (const TimeFunction& f : {TimeFunction::triangle(0.5, 1, 2, 3), TimeFunction::ramp(1, 2, -1),
                                TimeFunction::tabulated({0, 1, 3}, {0, 2, -1})}) {
    ASSERT_TRUE(f.piecewiseLinear(times, values)) << f.describe();
    const TimeFunction rebuilt = TimeFunction::tabulated(times, values);
    for (Real t = -1; t < 6; t += 0.0625) EXPECT_NEAR(rebuilt(t), f(t), 1e-14) << f.describe() << " t = " << t;
  }
  times = {7};
  EXPECT_FALSE(TimeFunction::ricker(2, 1).piecewiseLinear(times, values));
  EXPECT_FALSE(TimeFunction::constant(1).piecewiseLinear(times, values));
  EXPECT_EQ(times, std::vector<Real>{7});  // left unchanged
}

TEST(TimeFunction, QuietAfterIsWhereTheFunctionEndsForGood) {
  const Real never = std::numeric_limits<Real>::infinity();
  EXPECT_EQ(TimeFunction::triangle(0, 1, 1).quietAfter(), 2);
  EXPECT_EQ(TimeFunction::tabulated({0, 1, 3, 4}, {0, 2, 0, 0}).quietAfter(), 3);
  EXPECT_EQ(TimeFunction::tabulated({0, 1}, {0, 2}).quietAfter(), never);
  EXPECT_EQ(TimeFunction::ramp(0, 1).quietAfter(), never);
  EXPECT_EQ(TimeFunction::constant(1).quietAfter(), never);
  EXPECT_EQ(TimeFunction::constant(0).quietAfter(), -never);
  const TimeFunction ricker = TimeFunction::ricker(2, 1);
  ASSERT_EQ(ricker.quietAfter(), 2.5);
  for (Real t = 2.5; t < 4; t += 0.01) EXPECT_LT(std::abs(ricker(t)), 1e-30) << t;
  for (Real t = 2.01; t < 4; t += 0.01) EXPECT_EQ(TimeFunction::triangle(0, 1, 1)(t), 0) << t;
}
