#include "integrators/StabilityLimit.hpp"

#include "core/Error.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <limits>

using namespace mfwave;

namespace {

// First y where |p(i y)| exceeds 1 + 1e-12 for a closed-form stability polynomial, by scan and
// bisection: an independent route to the limits the Butcher-table code finds.
template <class P>
double closedFormLimit(P p) {
  const auto grows = [&](double y) { return std::abs(p(std::complex<double>(0, y))) > 1 + 1e-12; };
  double previous = 0;
  for (double y = 1e-4; y < 10; y += 1e-4) {
    if (grows(y)) {
      double lo = previous, hi = y;
      for (int k = 0; k < 60; ++k) {
        const double mid = 0.5 * (lo + hi);
        (grows(mid) ? hi : lo) = mid;
      }
      return lo;
    }
    previous = y;
  }
  return 10;
}

}  // namespace

TEST(StabilityLimit, ClassicRk4AmplificationIsItsTaylorPolynomial) {
  const ButcherCoefficients rk4 = ArkodeExplicit::coefficients("classic_rk4");
  for (double y : {0.3, 1.0, 2.0, 2.9}) {
    const std::complex<double> z(0, y);
    const double exact = std::abs(1.0 + z + z * z / 2.0 + z * z * z / 6.0 + z * z * z * z / 24.0);
    EXPECT_NEAR(rungeKuttaAmplification(rk4, y), exact, 1e-14) << y;
  }
}

TEST(StabilityLimit, ImaginaryAxisLimitsOfKnownTables) {
  // Classic RK4: |R(i y)|^2 = 1 - y^6 / 72 + y^8 / 576, so the limit is 2 sqrt 2.
  EXPECT_NEAR(integratorLimit("arkode:classic_rk4").omegaDtLimit, 2 * std::sqrt(2.0), 1e-9);
  // Any 3-stage third-order table: |R(i y)|^2 = 1 - y^4 / 12 + y^6 / 36, limit sqrt 3.
  EXPECT_NEAR(integratorLimit("arkode:knoth_wolke_3_3").omegaDtLimit, std::sqrt(3.0), 1e-9);
  // Dormand-Prince 5(4): R(z) = sum_{k <= 5} z^k / k! + z^6 / 600; its limit just below 1.
  const double dp = closedFormLimit([](std::complex<double> z) {
    std::complex<double> term = 1, sum = 1;
    for (int k = 1; k <= 5; ++k) sum += (term *= z / double(k));
    return sum + std::pow(z, 6) / 600.0;
  });
  EXPECT_NEAR(dp, 0.99719, 1e-4);
  EXPECT_NEAR(integratorLimit("arkode:dormand_prince_7_4_5").omegaDtLimit, dp, 1e-6);
}

TEST(StabilityLimit, HeunEulerGrowsAtEveryStep) {
  // R(z) = 1 + z + z^2 / 2: |R(i y)|^2 = 1 + y^4 / 4 > 1 for every y > 0.
  const IntegratorLimit heun = integratorLimit("arkode:heun_euler_2_1_2");
  EXPECT_LT(heun.omegaDtLimit, 0.01);
  EXPECT_NEAR(heun.growthPerStepAtOne, std::sqrt(1.25) - 1, 1e-12);
}

TEST(StabilityLimit, CentralDifferenceAndNewmarkLimits) {
  EXPECT_EQ(integratorLimit("central_difference").omegaDtLimit, 2);
  EXPECT_EQ(integratorLimit("leapfrog").omegaDtLimit, 2);
  EXPECT_EQ(integratorLimit("newmark").omegaDtLimit, std::numeric_limits<double>::infinity());
  EXPECT_DOUBLE_EQ(integratorLimit("newmark", 0, 0.5).omegaDtLimit, 2);             // central difference
  EXPECT_DOUBLE_EQ(integratorLimit("newmark", 1.0 / 12, 0.5).omegaDtLimit, std::sqrt(6.0));  // Fox-Goodwin
  EXPECT_EQ(integratorLimit("newmark", 0.25, 0.4).omegaDtLimit, 0);
  // Named in one word, as the stability atlas confirms them.
  EXPECT_DOUBLE_EQ(integratorLimit("newmark:fox_goodwin").omegaDtLimit, std::sqrt(6.0));
  EXPECT_DOUBLE_EQ(integratorLimit("newmark:linear_acceleration").omegaDtLimit, 2 * std::sqrt(3.0));
  EXPECT_DOUBLE_EQ(integratorLimit("newmark:0.1").omegaDtLimit, 1 / std::sqrt(0.15));
  EXPECT_EQ(integratorLimit("newmark:0.1").integrator, "newmark:0.1");
  EXPECT_EQ(integratorLimit("newmark:0.25").omegaDtLimit, std::numeric_limits<double>::infinity());
}

TEST(StabilityLimit, EveryOfferedIntegratorHasALimitAndUnknownNamesAreRefused) {
  const auto all = integratorLimits();
  EXPECT_EQ(all.size(), 5 + ArkodeExplicit::tableNames().size());  // Newmark: 1/4, 1/6, 1/12
  for (const auto& limit : all) EXPECT_GE(limit.omegaDtLimit, 0) << limit.integrator;
  EXPECT_THROW(integratorLimit("euler"), InputError);
  EXPECT_THROW(integratorLimit("arkode:no_such_table"), InputError);
  EXPECT_THROW(integratorLimit("newmark:0.6"), InputError);
  EXPECT_THROW(integratorLimit("newmark:fast"), InputError);
}

TEST(StabilityLimit, TheGrowthPerStepTurnsAboveOneExactlyAtTheLimit) {
  // A step just below the limit leaves the fastest mode bounded, one just above grows: for central
  // difference, a conditionally stable Newmark (beta = 0.1: L = 1 / sqrt(0.15)) and classic RK4.
  IntegratorOptions newmark;
  newmark.newmarkBeta = 0.1;
  IntegratorOptions rk4;
  rk4.arkode.table = "classic_rk4";
  const double omega = 7;
  for (const auto& [name, options] : {std::pair{std::string("central_difference"), IntegratorOptions{}},
                                      std::pair{std::string("newmark"), newmark},
                                      std::pair{std::string("arkode"), rk4}}) {
    const StepVerdict at = judgeStep(name, options, omega, 1);
    const double limitDt = at.limitDt;
    const StepVerdict below = judgeStep(name, options, omega, 0.999 * limitDt);
    const StepVerdict above = judgeStep(name, options, omega, 1.001 * limitDt);
    EXPECT_FALSE(below.aboveLimit) << name;
    EXPECT_LE(below.growthPerStep, 1 + 1e-12) << name;
    EXPECT_TRUE(above.aboveLimit) << name;
    EXPECT_GT(above.growthPerStep, 1 + 1e-6) << name;
    EXPECT_FALSE(above.integratorUnstable) << name;
  }
  EXPECT_NEAR(judgeStep("newmark", newmark, omega, 1).limitDt, 1 / std::sqrt(0.15) / omega, 1e-12);
  // Central difference at omega dt = 2.04: the root of lambda^2 + 2.1616 lambda + 1 = 0.
  EXPECT_NEAR(judgeStep("leapfrog", {}, 1, 2.04).growthPerStep, (2.1616 + std::sqrt(2.1616 * 2.1616 - 4)) / 2, 1e-12);
}

TEST(StabilityLimit, IntegratorsThatGrowAtAnyStepAreNamedAsSuch) {
  IntegratorOptions gamma;
  gamma.newmarkGamma = 0.3;
  const StepVerdict newmark = judgeStep("newmark", gamma, 1, 0.01);
  EXPECT_TRUE(newmark.integratorUnstable);
  EXPECT_TRUE(newmark.aboveLimit);
  EXPECT_GT(newmark.growthPerStep, 1);
  IntegratorOptions heun;
  heun.arkode.table = "heun_euler_2_1_2";
  const StepVerdict euler = judgeStep("arkode", heun, 1, 0.5);
  EXPECT_TRUE(euler.integratorUnstable);
  EXPECT_NEAR(euler.growthPerStep, std::sqrt(1 + std::pow(0.5, 4) / 4), 1e-12);
  // Average acceleration and adaptive ARKODE have no fixed-step limit.
  EXPECT_FALSE(judgeStep("newmark", {}, 1, 100).aboveLimit);
  IntegratorOptions adaptive;
  adaptive.arkode.table = "dormand_prince_7_4_5";
  adaptive.arkode.adaptive = true;
  EXPECT_FALSE(judgeStep("arkode", adaptive, 1, 100).aboveLimit);
  EXPECT_THROW(judgeStep("newmark", {}, 0, 1), InputError);
}
