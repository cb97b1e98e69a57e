// lib/methods/spectral_element/GaussLobattoLegendre: the GLL points and weights against their closed
// forms for N = 2, 3, 4, exactness for degree 2N - 1, and the derivative matrix on polynomials of
// degree N.

#include "core/Error.hpp"
#include "methods/spectral_element/GaussLobattoLegendre.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace mfwave {
namespace {

void expectRule(int order, const std::vector<Real>& nodes, const std::vector<Real>& weights) {
  const QuadratureRule rule = gaussLobattoLegendre(order);
  ASSERT_EQ(rule.nodes.size(), nodes.size());
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    EXPECT_NEAR(rule.nodes[i], nodes[i], 1e-15) << "order " << order << " node " << i;
    EXPECT_NEAR(rule.weights[i], weights[i], 1e-15) << "order " << order << " weight " << i;
  }
}

TEST(GaussLobattoLegendre, PointsAndWeightsMatchTheirClosedForms) {
  expectRule(1, {-1, 1}, {1, 1});
  expectRule(2, {-1, 0, 1}, {1.0 / 3, 4.0 / 3, 1.0 / 3});
  const Real a = 1 / std::sqrt(5.0);
  expectRule(3, {-1, -a, a, 1}, {1.0 / 6, 5.0 / 6, 5.0 / 6, 1.0 / 6});
  const Real b = std::sqrt(3.0 / 7.0);
  expectRule(4, {-1, -b, 0, b, 1}, {0.1, 49.0 / 90, 32.0 / 45, 49.0 / 90, 0.1});
}

TEST(GaussLobattoLegendre, IntegratesPolynomialsOfDegreeTwoNMinusOneExactly) {
  for (int order = 1; order <= 8; ++order) {
    const QuadratureRule rule = gaussLobattoLegendre(order);
    for (int degree = 0; degree <= 2 * order - 1; ++degree) {
      Real sum = 0;
      for (std::size_t i = 0; i < rule.nodes.size(); ++i) sum += rule.weights[i] * std::pow(rule.nodes[i], degree);
      const Real exact = degree % 2 == 0 ? 2.0 / (degree + 1) : 0.0;
      EXPECT_NEAR(sum, exact, 1e-14) << "order " << order << " degree " << degree;
    }
    // and not degree 2N (the rule's known defect): x^(2N) is integrated wrong
    Real sum = 0;
    for (std::size_t i = 0; i < rule.nodes.size(); ++i) sum += rule.weights[i] * std::pow(rule.nodes[i], 2 * order);
    EXPECT_GT(std::abs(sum - 2.0 / (2 * order + 1)), 1e-6) << "order " << order;
  }
}

TEST(GaussLobattoLegendre, DerivativeMatrixDifferentiatesPolynomialsOfDegreeN) {
  for (int order = 1; order <= 8; ++order) {
    const QuadratureRule rule = gaussLobattoLegendre(order);
    const Eigen::MatrixXd d = lagrangeDerivativeMatrix(rule.nodes);
    for (int degree = 0; degree <= order; ++degree) {
      Vector values(static_cast<Index>(rule.nodes.size()));
      for (std::size_t i = 0; i < rule.nodes.size(); ++i) values[static_cast<Index>(i)] = std::pow(rule.nodes[i], degree);
      const Vector derivative = d * values;
      for (std::size_t i = 0; i < rule.nodes.size(); ++i) {
        const Real exact = degree == 0 ? 0.0 : degree * std::pow(rule.nodes[i], degree - 1);
        EXPECT_NEAR(derivative[static_cast<Index>(i)], exact, 1e-12) << "order " << order << " degree " << degree;
      }
    }
  }
}

TEST(GaussLobattoLegendre, RefusesOrderZero) { EXPECT_THROW(gaussLobattoLegendre(0), InputError); }

}  // namespace
}  // namespace mfwave
