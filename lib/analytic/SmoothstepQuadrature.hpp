#pragma once
// Gauss-Legendre on consecutive pieces, each mapped by the smoothstep t = lo + h (3u^2 - 2u^3).
// The map's Jacobian vanishes like u at both ends, so an endpoint where the integrand behaves like
// sqrt(t - a) (a kink at a wavefront) or 1/sqrt(t - a) (a Cagniard path's arrival) becomes a
// smooth integrand in u: the exact Lamb solutions split their integrals at every front and
// integrate each piece this way to about 1e-12.

#include "core/GaussLegendre.hpp"
#include "core/Types.hpp"

#include <algorithm>
#include <vector>

namespace mfwave {

// sum over the pieces between consecutive (sorted) cuts of int f; empty pieces are skipped.
template <class F>
Real integrateSmoothstepPieces(std::vector<Real> cuts, const QuadratureRule& rule, F&& f) {
  std::sort(cuts.begin(), cuts.end());
  Real total = 0;
  for (std::size_t j = 0; j + 1 < cuts.size(); ++j) {
    const Real lo = cuts[j], h = cuts[j + 1] - lo;
    if (!(h > 0)) continue;
    Real sum = 0;
    for (std::size_t i = 0; i < rule.nodes.size(); ++i) {
      const Real u = 0.5 * (rule.nodes[i] + 1);
      // weights on [-1, 1] -> [0, 1] halve; dt/du = 6 h u (1 - u).
      sum += rule.weights[i] * 3 * h * u * (1 - u) * f(lo + h * u * u * (3 - 2 * u));
    }
    total += sum;
  }
  return total;
}

}  // namespace mfwave
