// Richardson extrapolation recovers the order and the limit of an exact power law from three
// samples at uneven spacings, and refuses data no single power law fits.

#include "numerics/RichardsonExtrapolation.hpp"

#include "core/Error.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace mfwave;

namespace {

ConvergenceSample sample(Real h, Real limit, Real constant, Real order) {
  return {h, limit + constant * std::pow(h, order)};
}

}  // namespace

TEST(RichardsonExtrapolation, RecoversOrderAndLimitOfAPowerLawAtUnevenSpacings) {
  for (Real order : {1.0, 2.0, 2.7}) {
    const ConvergenceSample a = sample(1.0 / 5, 0.2565, 5.0, order);
    const ConvergenceSample b = sample(1.0 / 7, 0.2565, 5.0, order);
    const ConvergenceSample c = sample(1.0 / 10, 0.2565, 5.0, order);
    const std::optional<Real> p = observedOrder(a, b, c);
    ASSERT_TRUE(p.has_value());
    EXPECT_NEAR(*p, order, 1e-9);
    EXPECT_NEAR(richardsonLimit(b, c, *p), 0.2565, 1e-12);
  }
}

TEST(RichardsonExtrapolation, SecondOrderLimitRemovesTheLeadingTermOnly) {
  // f = 1 + h^2 + h^3: the second-order limit from h = 0.2, 0.1 cancels h^2 exactly and leaves
  // 0.001 + (0.001 - 0.008) / 3 = -0.004 / 3 of the h^3 term.
  const auto f = [](Real h) { return ConvergenceSample{h, 1 + h * h + h * h * h}; };
  const Real limit = richardsonLimit(f(0.2), f(0.1), 2);
  EXPECT_NEAR(limit, 1 - 0.004 / 3, 1e-12);
  EXPECT_LT(std::abs(limit - 1), std::abs(f(0.1).value - 1) / 5);
}

TEST(RichardsonExtrapolation, NonMonotoneDataHasNoOrderAndBadSpacingsAreRejected) {
  EXPECT_FALSE(observedOrder({0.3, 1.0}, {0.2, 1.2}, {0.1, 1.1}).has_value());
  EXPECT_THROW(observedOrder({0.1, 1.0}, {0.2, 1.2}, {0.3, 1.1}), InputError);
  EXPECT_THROW(richardsonLimit({0.1, 1.0}, {0.1, 1.2}, 2), InputError);
  EXPECT_THROW(richardsonLimit({-0.1, 1.0}, {0.1, 1.2}, 2), InputError);
}

TEST(RichardsonExtrapolation, ASeriesUsesTheThreeFinestForItsOrderAndTheTwoFinestForItsLimit) {
  // f = 2 + 3 h^1.5 at five spacings given in no order: the order through the three finest, the
  // limit from the two finest with that order, both exact for a pure power law.
  const auto f = [](Real h) { return ConvergenceSample{h, 2 + 3 * std::pow(h, 1.5)}; };
  const auto series = richardsonSeries({f(0.1), f(0.4), f(0.025), f(0.2), f(0.05)});
  ASSERT_TRUE(series.has_value());
  EXPECT_EQ(series->resolutions, 5u);
  ASSERT_TRUE(series->observedOrder.has_value());
  EXPECT_NEAR(*series->observedOrder, 1.5, 1e-8);
  EXPECT_NEAR(series->orderUsed, 1.5, 1e-8);
  EXPECT_NEAR(series->limit, 2, 1e-8);

  // Two samples: no observed order, the assumed one gives the limit.
  const auto two = richardsonSeries({f(0.1), f(0.2)}, 1.5);
  ASSERT_TRUE(two.has_value());
  EXPECT_FALSE(two->observedOrder.has_value());
  EXPECT_EQ(two->orderUsed, 1.5);
  EXPECT_NEAR(two->limit, 2, 1e-12);
  EXPECT_FALSE(richardsonSeries({f(0.1)}).has_value());
}
