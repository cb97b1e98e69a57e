#pragma once
// Observed orders of convergence of a refinement series: how fast an error falls as the spacing
// falls, between each resolution and the next coarser one. deal.II's ConvergenceTable (its
// reduction rate against a reference column) is the model; here any ratio of spacings is allowed.
// Every convergence study reports these in its table and its summary; RichardsonExtrapolation
// finds the order through three resolutions without a known limit instead.

#include "core/Types.hpp"

#include <cmath>
#include <functional>
#include <vector>

namespace mfwave {

// p = log(e_coarse / e_fine) / log(h_coarse / h_fine): e = C h^p through both points.
Real pairwiseOrder(Real coarseSpacing, Real coarseError, Real fineSpacing, Real fineError);

// The order of each row of a series (coarse to fine) against the row before it, when
// `sameSeries(previous, row)` (several series in one list, one per integrator say); NaN for the
// first row of each series. `spacing` and `error` read a row (a member pointer or a function), so
// a driver's own case records serve as they are.
template <class Row, class Spacing, class Error, class SameSeries>
std::vector<Real> observedOrders(const std::vector<Row>& rows, Spacing spacing, Error error, SameSeries sameSeries) {
  std::vector<Real> orders(rows.size(), std::nan(""));
  for (std::size_t i = 1; i < rows.size(); ++i)
    if (sameSeries(rows[i - 1], rows[i]))
      orders[i] = pairwiseOrder(std::invoke(spacing, rows[i - 1]), std::invoke(error, rows[i - 1]),
                                std::invoke(spacing, rows[i]), std::invoke(error, rows[i]));
  return orders;
}

// The same for one series.
template <class Row, class Spacing, class Error>
std::vector<Real> observedOrders(const std::vector<Row>& rows, Spacing spacing, Error error) {
  return observedOrders(rows, spacing, error, [](const Row&, const Row&) { return true; });
}

// The same, stored in each row's `order` member (a table then reads one row per line).
template <class Row, class Spacing, class Error, class SameSeries>
void storeObservedOrders(std::vector<Row>& rows, Spacing spacing, Error error, Real Row::*order, SameSeries sameSeries) {
  const std::vector<Real> orders = observedOrders(rows, spacing, error, sameSeries);
  for (std::size_t i = 0; i < rows.size(); ++i) rows[i].*order = orders[i];
}

template <class Row, class Spacing, class Error>
void storeObservedOrders(std::vector<Row>& rows, Spacing spacing, Error error, Real Row::*order) {
  storeObservedOrders(rows, spacing, error, order, [](const Row&, const Row&) { return true; });
}

}  // namespace mfwave
