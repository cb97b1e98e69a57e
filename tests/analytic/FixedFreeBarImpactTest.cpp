#include "analytic/FixedFreeBarImpact.hpp"
#include "core/Error.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace mfwave;

namespace {
const double L = 10, c = std::sqrt(10.0), v0 = -1;
}

TEST(FixedFreeBarImpact, InitialAndBoundaryConditions) {
  const FixedFreeBarImpact bar(L, c, v0);
  for (double x : {0.5, 3.0, 7.7, 9.99}) {
    EXPECT_NEAR(bar.displacement(x, 0), 0, 1e-15);
    EXPECT_NEAR(bar.velocity(x, 0), v0, 1e-15);
  }
  for (double t : {0.1, 1.3, 4.0, 9.5, 17.2}) {
    EXPECT_NEAR(bar.displacement(0, t), 0, 1e-14) << t;          // fixed end
    EXPECT_NEAR(bar.strain(L - 1e-9, t), 0, 1e-14) << t;         // free end: E u_x = 0
    EXPECT_NEAR(bar.strain(L, t), 0, 1e-14) << t;
  }
}

TEST(FixedFreeBarImpact, KnownValuesOfTheTravellingFront) {
  const FixedFreeBarImpact bar(L, c, v0);
  // Before the front from x = 0 arrives (x > c t), the bar moves rigidly: u = v0 t, v = v0.
  EXPECT_NEAR(bar.displacement(8.0, 1.0), v0 * 1.0, 1e-14);
  EXPECT_NEAR(bar.velocity(8.0, 1.0), v0, 1e-15);
  // Behind the front (x < c t < L) the bar is at rest with strain v0 / c... u = v0 x / c.
  EXPECT_NEAR(bar.displacement(1.0, 1.0), v0 * 1.0 / c, 1e-14);
  EXPECT_NEAR(bar.velocity(1.0, 1.0), 0, 1e-15);
  EXPECT_NEAR(bar.strain(1.0, 1.0), v0 / c, 1e-15);
  // Periodic with period 4 L / c; at half a period the velocity is reversed and u = 0.
  const double T = bar.period();
  EXPECT_NEAR(T, 4 * L / c, 1e-14);
  EXPECT_NEAR(bar.displacement(4.2, 0.3 + T), bar.displacement(4.2, 0.3), 1e-12);
  EXPECT_NEAR(bar.displacement(4.2, T / 2), 0, 1e-12);
  EXPECT_NEAR(bar.velocity(4.2, T / 2), -v0, 1e-15);
}

TEST(FixedFreeBarImpact, SatisfiesTheWaveEquationAwayFromFronts) {
  const FixedFreeBarImpact bar(L, c, v0);
  auto u = [&](double x, double t) { return bar.displacement(x, t); };
  const double e = 1e-3;
  for (auto [x, t] : {std::pair{2.0, 0.3}, std::pair{6.0, 2.5}, std::pair{9.0, 5.1}}) {
    const double utt = (u(x, t + e) - 2 * u(x, t) + u(x, t - e)) / (e * e);
    const double uxx = (u(x + e, t) - 2 * u(x, t) + u(x - e, t)) / (e * e);
    EXPECT_NEAR(utt - c * c * uxx, 0, 1e-6);
    EXPECT_NEAR(bar.velocity(x, t), (u(x, t + e) - u(x, t - e)) / (2 * e), 1e-9);
    EXPECT_NEAR(bar.strain(x, t), (u(x + e, t) - u(x - e, t)) / (2 * e), 1e-9);
  }
  // Energy is conserved: int (rho v^2 + E u_x^2) / 2 dx = rho v0^2 L / 2 (midpoint rule, fine grid).
  for (double t : {0.7, 3.3, 11.0}) {
    double energy = 0;
    const int n = 100000;
    for (int i = 0; i < n; ++i) {
      const double x = (i + 0.5) * L / n;
      energy += 0.5 * (std::pow(bar.velocity(x, t), 2) + c * c * std::pow(bar.strain(x, t), 2)) * L / n;
    }
    EXPECT_NEAR(energy, 0.5 * v0 * v0 * L, 1e-3) << t;
  }
}

TEST(FixedFreeBarImpact, RejectsBadParameters) {
  EXPECT_THROW(FixedFreeBarImpact(0, 1, 1), InputError);
  EXPECT_THROW(FixedFreeBarImpact(1, -1, 1), InputError);
}
