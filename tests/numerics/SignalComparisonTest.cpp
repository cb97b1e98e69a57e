#include "numerics/SignalComparison.hpp"
#include "core/Error.hpp"
#include "support/InputErrorKey.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace mfwave;
using mfwave::testing::inputErrorKey;

namespace {

Real pulse(Real t, Real centre) { return -std::exp(-std::pow((t - centre) / 0.3, 2)); }

}  // namespace

// A pulse scaled by 0.9 and delayed by 0.1: peak error -10 %, arrival error +0.1, and the L2 error
// of a scaled copy alone is exactly 0.1.
TEST(SignalComparison, ScaledAndDelayedPulse) {
  std::vector<Real> t, exact, scaled, delayed;
  for (int i = 0; i <= 6000; ++i) {
    t.push_back(i * 1e-3);
    exact.push_back(pulse(t.back(), 2));
    scaled.push_back(0.9 * exact.back());
    delayed.push_back(0.9 * pulse(t.back(), 2.1));
  }
  const SignalErrors s = compareSignals(t, scaled, exact, 6);
  EXPECT_NEAR(s.relativeL2, 0.1, 1e-12);
  EXPECT_NEAR(s.peakExact, -1, 1e-12);
  EXPECT_NEAR(s.peakError, -0.1, 1e-12);
  EXPECT_NEAR(s.arrivalExact, 2 - 0.3 * std::sqrt(std::log(10.0)), 1e-6);

  const SignalErrors d = compareSignals(t, delayed, exact, 6);
  EXPECT_NEAR(d.peakComputed, -0.9, 1e-6);
  // 0.9 times the pulse crosses 0.1 a little later than the pulse itself: 0.3 sqrt(ln 9) from its centre.
  EXPECT_NEAR(d.arrivalError, 0.1 + 0.3 * (std::sqrt(std::log(10.0)) - std::sqrt(std::log(9.0))), 1e-6);
  // int (0.9 p(t - 0.1) - p(t))^2 / int p^2 = 0.81 + 1 - 1.8 exp(-0.1^2 / (2 0.3^2)) for Gaussians.
  EXPECT_NEAR(d.relativeL2, std::sqrt(1.81 - 1.8 * std::exp(-0.01 / 0.18)), 1e-6);
}

TEST(SignalComparison, WindowLimitsTheComparison) {
  const std::vector<Real> t{0, 1, 2, 3}, exact{0, 1, 0, 0}, computed{0, 1, 0, 5};
  EXPECT_DOUBLE_EQ(compareSignals(t, computed, exact, 2).relativeL2, 0);
  EXPECT_GT(compareSignals(t, computed, exact, 3).relativeL2, 1);
}

TEST(SignalComparison, NeverArrivingSignalGivesNaN) {
  const std::vector<Real> t{0, 1, 2}, exact{0, 1, 0}, computed{0, 0.01, 0};
  EXPECT_TRUE(std::isnan(compareSignals(t, computed, exact, 2).arrivalComputed));
}

TEST(SignalComparison, BadInputNamesTheArgument) {
  const std::vector<Real> t{0, 1, 2}, z{0, 0, 0};
  EXPECT_EQ(inputErrorKey([&] { compareSignals(t, z, z, 2); }), "exact");
  EXPECT_EQ(inputErrorKey([&] { compareSignals(t, {0, 1}, z, 2); }), "times");
  EXPECT_EQ(inputErrorKey([&] { compareSignals({0, 0, 1}, z, {0, 1, 0}, 2); }), "times");
}
