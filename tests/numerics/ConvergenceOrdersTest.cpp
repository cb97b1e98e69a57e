#include "numerics/ConvergenceOrders.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

using namespace mfwave;

namespace {

struct Case {
  std::string series;
  Real h;
  Real error;
};

}  // namespace

// e = 3 h^2 halving h, then e = 0.5 h^4 over spacings in ratio 3: the orders are the exponents.
TEST(ConvergenceOrders, RecoverThePowerOfAnExactPowerLaw) {
  EXPECT_NEAR(pairwiseOrder(0.1, 3 * 0.01, 0.05, 3 * 0.0025), 2.0, 1e-12);
  std::vector<Case> rows;
  for (Real h : {0.3, 0.1, 1.0 / 30}) rows.push_back({"quartic", h, 0.5 * std::pow(h, 4)});
  const std::vector<Real> orders = observedOrders(rows, &Case::h, &Case::error);
  ASSERT_EQ(orders.size(), 3u);
  EXPECT_TRUE(std::isnan(orders[0]));
  EXPECT_NEAR(orders[1], 4.0, 1e-12);
  EXPECT_NEAR(orders[2], 4.0, 1e-12);
}

// Two series in one list: no order across the boundary between them.
TEST(ConvergenceOrders, StartEachSeriesAfresh) {
  const std::vector<Case> rows{{"a", 0.2, 0.04}, {"a", 0.1, 0.01}, {"b", 0.2, 0.2}, {"b", 0.1, 0.1}};
  const auto sameSeries = [](const Case& x, const Case& y) { return x.series == y.series; };
  const std::vector<Real> orders = observedOrders(rows, &Case::h, &Case::error, sameSeries);
  EXPECT_TRUE(std::isnan(orders[0]));
  EXPECT_NEAR(orders[1], 2.0, 1e-12);
  EXPECT_TRUE(std::isnan(orders[2]));
  EXPECT_NEAR(orders[3], 1.0, 1e-12);
}

// The orders stored in the rows themselves, series by series.
TEST(ConvergenceOrders, StoreEachRowsOrderInTheRow) {
  struct Row {
    std::string series;
    Real h, error, order;
  };
  std::vector<Row> rows{{"a", 0.2, 0.04, 0}, {"a", 0.1, 0.01, 0}, {"b", 0.2, 0.2, 0}, {"b", 0.1, 0.1, 0}};
  storeObservedOrders(rows, &Row::h, &Row::error, &Row::order,
                      [](const Row& x, const Row& y) { return x.series == y.series; });
  EXPECT_TRUE(std::isnan(rows[0].order));
  EXPECT_NEAR(rows[1].order, 2.0, 1e-12);
  EXPECT_TRUE(std::isnan(rows[2].order));
  EXPECT_NEAR(rows[3].order, 1.0, 1e-12);
  storeObservedOrders(rows, &Row::h, &Row::error, &Row::order);
  EXPECT_NEAR(rows[2].order, std::log(0.01 / 0.2) / std::log(0.1 / 0.2), 1e-12);
}
