#pragma once
// Richardson extrapolation of a quantity f(h) = f0 + C h^p + ... measured at several spacings:
// the observed order p from three spacings (any ratios) and the extrapolated limit f0. The plate
// study uses it on the period against particles across the thickness; any convergence study can.

#include "core/Types.hpp"

#include <optional>

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

}  // namespace mfwave
