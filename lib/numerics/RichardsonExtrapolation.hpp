#pragma once
// Richardson extrapolation of a quantity f(h) = f0 + C h^p + ... measured at several spacings:
// the observed order p from three spacings (any ratios) and the extrapolated limit f0. The plate
// study uses it on the period against particles across the thickness; any convergence study can.

#include "core/Types.hpp"

#include <cstddef>
#include <optional>
#include <vector>

namespace mfwave {

struct ConvergenceSample {
  Real spacing;  // h (or 1 / resolution)
  Real value;    // f(h)
};

// The order p with f(h_i) = f0 + C h_i^p through three samples of distinct spacings, found by
// bisection on p in [minOrder, maxOrder]. Empty when the three values are not monotone in h (no
// single power law passes through them) or when the root lies outside the bracket.
std::optional<Real> observedOrder(const ConvergenceSample& coarse, const ConvergenceSample& middle,
                                  const ConvergenceSample& fine, Real minOrder = 0.25, Real maxOrder = 8);

// f0 = f(fine) + (f(fine) - f(coarse)) / ((h_coarse / h_fine)^p - 1).
Real richardsonLimit(const ConvergenceSample& coarse, const ConvergenceSample& fine, Real order);

// A series over resolutions reduced to its limit: the order observed through the three finest
// samples (empty with only two, or when the three are not monotone; `assumedOrder` is used then)
// and the Richardson limit from the two finest with the order used.
struct RichardsonSeries {
  std::size_t resolutions = 0;
  std::optional<Real> observedOrder;
  Real orderUsed = 2;
  Real limit = 0;
};

// The samples in any order (sorted here, coarsest first); empty with fewer than two.
std::optional<RichardsonSeries> richardsonSeries(std::vector<ConvergenceSample> samples, Real assumedOrder = 2);

}  // namespace mfwave
