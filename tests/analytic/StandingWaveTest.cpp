#include "analytic/StandingWave.hpp"
#include "core/Error.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace mfwave;

TEST(StandingWave, SatisfiesTheWaveEquationAndTheFixedEnds) {
  const StandingWave wave(3, 2.0, 1.5, 0.7, -1.0);
  EXPECT_NEAR(wave.displacement(-1.0, 0.3), 0, 1e-15);
  EXPECT_NEAR(wave.displacement(1.0, 0.3), 0, 1e-14);
  // u_tt - c^2 u_xx = 0 by central differences (step 1e-3, error ~ 1e-6 relative).
  const double x = 0.123, t = 0.456, e = 1e-3, c = 1.5;
  auto u = [&](double xx, double tt) { return wave.displacement(xx, tt); };
  const double utt = (u(x, t + e) - 2 * u(x, t) + u(x, t - e)) / (e * e);
  const double uxx = (u(x + e, t) - 2 * u(x, t) + u(x - e, t)) / (e * e);
  EXPECT_NEAR(utt, c * c * uxx, 1e-4 * std::abs(utt));
  EXPECT_NEAR(wave.velocity(x, t), (u(x, t + e) - u(x, t - e)) / (2 * e), 1e-5);
  EXPECT_NEAR(wave.period(), 2 * 2.0 / (3 * 1.5), 1e-15);
}

TEST(StandingWave, RejectsBadParameters) {
  EXPECT_THROW(StandingWave(0, 1, 1), InputError);
  EXPECT_THROW(StandingWave(1, -1, 1), InputError);
  EXPECT_THROW(StandingWave(1, 1, 0), InputError);
}
