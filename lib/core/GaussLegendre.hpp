#pragma once
// Gauss-Legendre quadrature: exact for polynomials of degree 2n - 1, which makes it exact on each
// polynomial piece of the spline kernels (normalisation checks, plane integrals); the exact Lamb
// solutions (lib/analytic) integrate their smooth-after-mapping kernels with it.

#include "core/Types.hpp"

#include <vector>

namespace mfwave {

struct QuadratureRule {
  std::vector<Real> nodes;    // on [-1, 1]
  std::vector<Real> weights;  // sum to 2
};

// n-point rule (n >= 1), nodes by Newton iteration on P_n to machine precision.
QuadratureRule gaussLegendre(int points);

// int_a^b f(x) dx with `rule` applied on each of `pieces` equal subintervals.
template <class F>
Real integrate(const QuadratureRule& rule, Real a, Real b, F&& f, int pieces = 1) {
  const Real width = (b - a) / pieces;
  const Real half = 0.5 * width;
  Real sum = 0.0;
  for (int p = 0; p < pieces; ++p) {
    const Real mid = a + (p + 0.5) * width;
    for (std::size_t i = 0; i < rule.nodes.size(); ++i) sum += rule.weights[i] * f(mid + half * rule.nodes[i]);
  }
  return half * sum;
}

}  // namespace mfwave
