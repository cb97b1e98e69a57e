#include "core/GaussLegendre.hpp"

#include "core/Error.hpp"

#include <cmath>
#include <string>

namespace mfwave {

namespace {

// P_n(x) and P_n'(x) by the three-term recurrence (|x| < 1).
void legendre(int n, Real x, Real& pn, Real& dpn) {
  Real p0 = 1.0;
  Real p1 = x;
  for (int k = 2; k <= n; ++k) {
    const Real p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
    p0 = p1;
    p1 = p2;
  }
  pn = p1;
  dpn = n * (x * p1 - p0) / (x * x - 1.0);
}

}  // namespace

QuadratureRule gaussLegendre(int points) {
  if (points < 1) throw InputError("quadrature_points", "must be >= 1, got " + std::to_string(points));
  const auto n = static_cast<std::size_t>(points);
  QuadratureRule rule{std::vector<Real>(n), std::vector<Real>(n)};
  // The roots are symmetric: Newton from the asymptotic guess for the upper half, mirror the rest.
  for (std::size_t i = 0; i < (n + 1) / 2; ++i) {
    Real x = std::cos(kPi * (static_cast<Real>(i) + 0.75) / (points + 0.5));
    Real pn = 0.0;
    Real dpn = 1.0;
    for (int iter = 0; iter < 100; ++iter) {
      legendre(points, x, pn, dpn);
      const Real dx = pn / dpn;
      x -= dx;
      if (std::abs(dx) <= 1e-16) break;
    }
    legendre(points, x, pn, dpn);
    const Real w = 2.0 / ((1.0 - x * x) * dpn * dpn);
    rule.nodes[i] = x;
    rule.weights[i] = w;
    rule.nodes[n - 1 - i] = -x;
    rule.weights[n - 1 - i] = w;
  }
  return rule;
}

}  // namespace mfwave
