#include "methods/spectral_element/GaussLobattoLegendre.hpp"

#include "core/Error.hpp"

#include <cmath>
#include <string>

namespace mfwave {

namespace {

struct LegendreValues {
  Real value = 0;           // P_N(x)
  Real derivative = 0;      // P_N'(x)
  Real secondDerivative = 0;  // P_N''(x)
};

// P_N and its first two derivatives at an interior point |x| < 1, from the three-term recurrence
// and Legendre's equation (1 - x^2) P'' = 2 x P' - N (N + 1) P.
LegendreValues legendre(int n, Real x) {
  Real previous = 1, current = x;  // P_0, P_1
  for (int k = 2; k <= n; ++k) {
    const Real next = ((2 * k - 1) * x * current - (k - 1) * previous) / k;
    previous = current;
    current = next;
  }
  LegendreValues p;
  p.value = n == 0 ? 1.0 : current;
  const Real oneMinusSquare = 1 - x * x;
  p.derivative = n == 0 ? 0.0 : n * (previous - x * current) / oneMinusSquare;
  p.secondDerivative = (2 * x * p.derivative - n * (n + 1) * p.value) / oneMinusSquare;
  return p;
}

Real legendreValue(int n, Real x) {
  Real previous = 1, current = x;
  for (int k = 2; k <= n; ++k) {
    const Real next = ((2 * k - 1) * x * current - (k - 1) * previous) / k;
    previous = current;
    current = next;
  }
  return n == 0 ? 1.0 : current;
}

}  // namespace

QuadratureRule gaussLobattoLegendre(int order) {
  if (order < 1) throw InputError("order", "GLL quadrature needs order N >= 1, got " + std::to_string(order));
  const int n = order;
  QuadratureRule rule;
  rule.nodes.assign(static_cast<std::size_t>(n + 1), 0.0);
  rule.nodes.front() = -1;
  rule.nodes.back() = 1;
  const Real pi = std::acos(-1.0);
  for (int i = 1; i < n; ++i) {
    // Chebyshev-Gauss-Lobatto start, close to the root of P_N' (Canuto et al. 2006, sec. 2.3)
    Real x = -std::cos(pi * i / n);
    for (int iteration = 0; iteration < 100; ++iteration) {
      const LegendreValues p = legendre(n, x);
      const Real step = p.derivative / p.secondDerivative;
      x -= step;
      if (std::abs(step) < 1e-16) break;
    }
    rule.nodes[static_cast<std::size_t>(i)] = x;
  }
  // symmetric to rounding: make it exact
  for (int i = 0; i <= n / 2; ++i) {
    const auto lo = static_cast<std::size_t>(i), hi = static_cast<std::size_t>(n - i);
    const Real x = 0.5 * (rule.nodes[hi] - rule.nodes[lo]);
    rule.nodes[lo] = -x;
    rule.nodes[hi] = x;
  }
  if (n % 2 == 0) rule.nodes[static_cast<std::size_t>(n / 2)] = 0;
  rule.weights.resize(rule.nodes.size());
  for (std::size_t i = 0; i < rule.nodes.size(); ++i) {
    const Real p = legendreValue(n, rule.nodes[i]);
    rule.weights[i] = 2.0 / (n * (n + 1) * p * p);
  }
  return rule;
}

Eigen::MatrixXd lagrangeDerivativeMatrix(const std::vector<Real>& nodes) {
  const auto count = static_cast<Index>(nodes.size());
  std::vector<Real> barycentric(nodes.size(), 1.0);
  for (std::size_t j = 0; j < nodes.size(); ++j)
    for (std::size_t k = 0; k < nodes.size(); ++k)
      if (k != j) barycentric[j] /= nodes[j] - nodes[k];
  Eigen::MatrixXd d = Eigen::MatrixXd::Zero(count, count);
  for (Index i = 0; i < count; ++i) {
    Real diagonal = 0;
    for (Index j = 0; j < count; ++j) {
      if (i == j) continue;
      const auto si = static_cast<std::size_t>(i), sj = static_cast<std::size_t>(j);
      d(i, j) = barycentric[sj] / barycentric[si] / (nodes[si] - nodes[sj]);
      diagonal -= d(i, j);
    }
    d(i, i) = diagonal;
  }
  return d;
}

}  // namespace mfwave
