#include "numerics/Oscillation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace mfwave;

// u = A sin(2 pi t / T) with ripples: the crossings at multiples of T / 2, the period T, the
// half-cycle amplitudes A, and no spurious crossings from ripples near zero.
TEST(Oscillation, FindsPeriodAndAmplitudeOfARipplingSine) {
  const Real period = 0.25, amplitude = 0.03;
  std::vector<Real> t, u;
  for (int k = 0; k <= 4000; ++k) {
    const Real time = 1.6 * k / 4000.0;  // 6.4 periods
    t.push_back(time);
    u.push_back(amplitude * std::sin(2 * kPi * time / period) + 1e-3 * amplitude * std::sin(2 * kPi * time / 0.001));
  }
  const Oscillation o = analyseOscillation(t, u);
  ASSERT_EQ(o.crossings.size(), 12u);  // T/2, T, ..., 6 T
  EXPECT_EQ(o.halfPeriods, 11);
  EXPECT_NEAR(o.crossings.front(), period / 2, 1e-5);
  EXPECT_NEAR(o.period, period, 1e-5);
  EXPECT_NEAR(o.firstAmplitude(), amplitude, 2e-3 * amplitude);
  EXPECT_NEAR(o.lastAmplitude(), amplitude, 2e-3 * amplitude);
  EXPECT_NEAR(o.earlyPeriod(2), period, 1e-5);
  EXPECT_NEAR(o.shortestPeriod(), period, 1e-5);
  EXPECT_NEAR(o.longestPeriod(), period, 1e-5);
}

// A chirp whose frequency rises: the shortest and longest single periods bracket the mean, and the
// longest is the first.
TEST(Oscillation, ShortestAndLongestBracketTheMeanOfAChirp) {
  std::vector<Real> t, u;
  for (int k = 0; k <= 20000; ++k) {
    const Real time = 4.0 * k / 20000.0;
    t.push_back(time);
    u.push_back(std::sin(2 * kPi * (time + 0.05 * time * time)));
  }
  const Oscillation o = analyseOscillation(t, u);
  EXPECT_LT(o.shortestPeriod(), o.period);
  EXPECT_GT(o.longestPeriod(), o.period);
  EXPECT_DOUBLE_EQ(o.longestPeriod(), o.earlyPeriod(1));
  EXPECT_LT(o.shortestPeriod(), o.earlyPeriod(1));
}

TEST(Oscillation, ReportsNothingForASignalThatNeverSwings) {
  const Oscillation flat = analyseOscillation({0, 1, 2, 3}, {0, 0, 0, 0});
  EXPECT_TRUE(std::isnan(flat.period));
  EXPECT_EQ(flat.halfPeriods, 0);
  EXPECT_TRUE(std::isnan(flat.firstAmplitude()));
  const Oscillation oneWay = analyseOscillation({0, 1, 2, 3}, {0, 1, 2, 3});
  EXPECT_TRUE(oneWay.crossings.empty());
}
