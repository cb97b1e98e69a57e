// The quadrature the normalisation and plane-integral results rest on.

#include "core/Error.hpp"
#include "core/GaussLegendre.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace mfwave {
namespace {

TEST(GaussLegendre, TwoPointRuleIsKnown) {
  const QuadratureRule rule = gaussLegendre(2);
  ASSERT_EQ(rule.nodes.size(), 2u);
  EXPECT_NEAR(rule.nodes[0], 1.0 / std::sqrt(3.0), 1e-15);
  EXPECT_NEAR(rule.nodes[1], -1.0 / std::sqrt(3.0), 1e-15);
  EXPECT_NEAR(rule.weights[0], 1.0, 1e-15);
  EXPECT_NEAR(rule.weights[1], 1.0, 1e-15);
}

TEST(GaussLegendre, ExactForPolynomialsUpToDegreeTwoNMinusOne) {
  for (int n = 1; n <= 20; ++n) {
    const QuadratureRule rule = gaussLegendre(n);
    // int_0^1.5 x^k dx = 1.5^{k+1} / (k+1)
    for (int k = 0; k <= 2 * n - 1; ++k) {
      const Real exact = std::pow(1.5, k + 1) / (k + 1);
      const Real got = integrate(rule, 0.0, 1.5, [k](Real x) { return std::pow(x, k); });
      EXPECT_NEAR(got, exact, 1e-14 * exact) << "n = " << n << ", k = " << k;
    }
    // ... and not beyond: degree 2n leaves a relative error 1/C(2n, n)^2, visible for small n.
    if (n > 8) continue;
    const Real exact = std::pow(1.5, 2 * n + 1) / (2 * n + 1);
    EXPECT_GT(std::abs(integrate(rule, 0.0, 1.5, [n](Real x) { return std::pow(x, 2 * n); }) - exact), 1e-12 * exact)
        << "n = " << n;
  }
}

TEST(GaussLegendre, CompositeRuleConvergesForSmoothFunctions) {
  const QuadratureRule rule = gaussLegendre(10);
  EXPECT_NEAR(integrate(rule, 0.0, 3.0, [](Real x) { return std::exp(-x * x); }, 6), 0.5 * std::sqrt(M_PI) * std::erf(3.0),
              1e-15);
}

TEST(GaussLegendre, RejectsNonPositivePointCount) {
  EXPECT_THROW((void)gaussLegendre(0), InputError);
}

}  // namespace
}  // namespace mfwave
