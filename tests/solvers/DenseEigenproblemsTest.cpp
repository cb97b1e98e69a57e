// The dense eigenvalue problems against closed forms: each result satisfies A v = lambda v, the
// ordering and normalisation the header promises, and a matrix the solvers cannot handle (NaN)
// throws naming the caller's description.
#include "solvers/DenseEigenproblems.hpp"

#include "core/Error.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <limits>
#include <string>

namespace mfwave {
namespace {

using Complex = std::complex<Real>;

Eigen::MatrixXd tridiagonal(int n) {
  // Fixed-fixed second difference: eigenvalues 2 - 2 cos(k pi / (n + 1)), k = 1..n.
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i) {
    a(i, i) = 2;
    if (i + 1 < n) a(i, i + 1) = a(i + 1, i) = -1;
  }
  return a;
}

TEST(DenseEigenproblems, SymmetricMatchesTheSecondDifferenceSpectrumInAscendingOrder) {
  const int n = 12;
  const Eigen::MatrixXd a = tridiagonal(n);
  const SymmetricEigenpairs pairs = symmetricEigenpairs(a);
  const Eigen::VectorXd values = symmetricEigenvalues(a);
  for (int k = 0; k < n; ++k) {
    const Real exact = 2 - 2 * std::cos((k + 1) * M_PI / (n + 1));
    EXPECT_NEAR(pairs.values[k], exact, 1e-14);
    EXPECT_NEAR(values[k], exact, 1e-14);
    EXPECT_NEAR((a * pairs.vectors.col(k) - exact * pairs.vectors.col(k)).norm(), 0.0, 1e-13);
  }
  EXPECT_NEAR((pairs.vectors.transpose() * pairs.vectors - Eigen::MatrixXd::Identity(n, n)).norm(), 0.0, 1e-13);
}

TEST(DenseEigenproblems, HermitianSymbolOfAPeriodicPairHasRealEigenvalues) {
  // [[2, 1 - e^{ik}], [1 - e^{-ik}, 2]]: eigenvalues 2 -+ |1 - e^{ik}| = 2 -+ 2 sin(k / 2).
  const Real k = 0.7;
  Eigen::MatrixXcd a(2, 2);
  a << 2, Complex(1, 0) - std::polar(1.0, k), Complex(1, 0) - std::polar(1.0, -k), 2;
  const HermitianEigenpairs pairs = hermitianEigenpairs(a);
  EXPECT_NEAR(pairs.values[0], 2 - 2 * std::sin(k / 2), 1e-14);
  EXPECT_NEAR(pairs.values[1], 2 + 2 * std::sin(k / 2), 1e-14);
  EXPECT_NEAR((hermitianEigenvalues(a) - pairs.values).norm(), 0.0, 1e-15);
  for (int j = 0; j < 2; ++j)
    EXPECT_NEAR((a * pairs.vectors.col(j) - pairs.values[j] * pairs.vectors.col(j)).norm(), 0.0, 1e-14);
}

TEST(DenseEigenproblems, GeneralRealAndComplexMatricesGiveTheirEigenpairs) {
  // A damped oscillator's first-order matrix [[0, 1], [-w^2, -2 z w]]: lambda = w (-z +- i sqrt(1 - z^2)).
  const Real w = 3, z = 0.1;
  Eigen::MatrixXd a(2, 2);
  a << 0, 1, -w * w, -2 * z * w;
  const GeneralEigenpairs real = generalEigenpairs(a, true);
  ASSERT_EQ(real.vectors.cols(), 2);
  for (int j = 0; j < 2; ++j) {
    EXPECT_NEAR(real.values[j].real(), -z * w, 1e-14);
    EXPECT_NEAR(std::abs(real.values[j].imag()), w * std::sqrt(1 - z * z), 1e-13);
    EXPECT_NEAR((a.cast<Complex>() * real.vectors.col(j) - real.values[j] * real.vectors.col(j)).norm(), 0.0, 1e-13);
  }
  EXPECT_EQ(generalEigenpairs(a, false).vectors.size(), 0);
  EXPECT_NEAR((generalEigenvalues(a) - real.values).norm(), 0.0, 1e-15);

  // An upper-triangular complex matrix: its diagonal.
  Eigen::MatrixXcd c(2, 2);
  c << Complex(1, 2), Complex(5, -1), 0, Complex(-3, 0.5);
  const GeneralEigenpairs complex = generalEigenpairs(c, true);
  Eigen::VectorXcd sorted = complex.values;
  if (sorted[0].real() > sorted[1].real()) std::swap(sorted[0], sorted[1]);
  EXPECT_NEAR(std::abs(sorted[0] - Complex(-3, 0.5)), 0.0, 1e-14);
  EXPECT_NEAR(std::abs(sorted[1] - Complex(1, 2)), 0.0, 1e-14);
  for (int j = 0; j < 2; ++j)
    EXPECT_NEAR((c * complex.vectors.col(j) - complex.values[j] * complex.vectors.col(j)).norm(), 0.0, 1e-13);
}

TEST(DenseEigenproblems, ANonFiniteMatrixThrowsNamingTheCaller) {
  Eigen::MatrixXd a = tridiagonal(4);
  a(1, 1) = std::numeric_limits<Real>::quiet_NaN();
  try {
    symmetricEigenvalues(a, "rest operator");
    FAIL() << "a NaN matrix must not give eigenvalues";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), "rest operator: the dense eigenvalue solver did not converge");
  }
  EXPECT_THROW(generalEigenvalues(a, "rest operator"), Error);
}

}  // namespace
}  // namespace mfwave
