// The complete polynomial basis behind the RK moment matrix (Luo-Liu-Huang eq. (4) in D variables).

#include <gtest/gtest.h>

#include <set>

#include "CollocationTestSupport.hpp"
#include "methods/collocation/PolynomialBasis.hpp"
#include "support/InputErrorKey.hpp"

using namespace mfwave;
using namespace mfwave::testing;

namespace {

template <int D>
void checkBasis(const std::array<int, 4>& expectedSizes) {
  for (int m = 0; m <= 3; ++m) {
    SCOPED_TRACE("D = " + std::to_string(D) + ", m = " + std::to_string(m));
    const PolynomialBasis<D> basis(m);
    EXPECT_EQ(basis.size(), expectedSizes[static_cast<std::size_t>(m)]);
    EXPECT_EQ(PolynomialBasis<D>::sizeFor(m), basis.size());
    // Every exponent with |alpha| <= m exactly once, graded (degree never decreases).
    std::set<std::array<int, D>> seen;
    int lastDegree = 0;
    for (int t = 0; t < basis.size(); ++t) {
      const std::array<int, D>& e = basis.exponent(t);
      int degree = 0;
      for (int a = 0; a < D; ++a) degree += e[static_cast<std::size_t>(a)];
      EXPECT_LE(degree, m);
      EXPECT_GE(degree, lastDegree);
      lastDegree = degree;
      seen.insert(e);
    }
    EXPECT_EQ(static_cast<int>(seen.size()), basis.size());
    // H(0) = e_0 (eq. (5)).
    BasisVector h;
    basis.evaluate(Vec<D>::Zero(), h);
    EXPECT_EQ(h[0], 1.0);
    EXPECT_EQ(h.tail(basis.size() - 1).cwiseAbs().sum(), 0.0);
    // Values and derivatives against the independent monomial formula.
    Vec<D> y;
    for (int a = 0; a < D; ++a) y[a] = 0.3 - 0.45 * a;
    typename PolynomialBasis<D>::Evaluation evaluation;
    basis.evaluate(y, 2, evaluation);
    for (int t = 0; t < basis.size(); ++t) {
      EXPECT_NEAR(evaluation.value[t], monomial<D>(basis.exponent(t), y), 1e-15);
      for (int j = 0; j < D; ++j) {
        EXPECT_NEAR(evaluation.gradient[static_cast<std::size_t>(j)][t], monomial<D>(basis.exponent(t), y, j), 1e-15);
        for (int k = 0; k < D; ++k)
          EXPECT_NEAR(evaluation.hessian[static_cast<std::size_t>(symmetricPairIndex<D>(j, k))][t],
                      monomial<D>(basis.exponent(t), y, j, k), 1e-15);
      }
    }
  }
}

}  // namespace

TEST(PolynomialBasis, CompleteBasisOfEachOrderAndDimension) {
  checkBasis<1>({1, 2, 3, 4});
  checkBasis<2>({1, 3, 6, 10});
  checkBasis<3>({1, 4, 10, 20});
}

TEST(PolynomialBasis, SymmetricPairIndexCoversTheUpperTriangleOnce) {
  EXPECT_EQ(symmetricPairIndex<3>(0, 0), 0);
  EXPECT_EQ(symmetricPairIndex<3>(0, 1), 1);
  EXPECT_EQ(symmetricPairIndex<3>(0, 2), 2);
  EXPECT_EQ(symmetricPairIndex<3>(1, 1), 3);
  EXPECT_EQ(symmetricPairIndex<3>(2, 1), 4);
  EXPECT_EQ(symmetricPairIndex<3>(2, 2), 5);
  EXPECT_EQ(symmetricPairIndex<2>(1, 0), 1);
  EXPECT_EQ(symmetricPairIndex<2>(1, 1), 2);
}

TEST(PolynomialBasis, UnsupportedOrderNamesTheKey) {
  EXPECT_EQ(inputErrorKey([] { PolynomialBasis<2>(4); }), "method.order");
  EXPECT_EQ(inputErrorKey([] { PolynomialBasis<2>(-1, "method.polynomial_degree"); }), "method.polynomial_degree");
}
