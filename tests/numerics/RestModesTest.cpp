// restOperator / restModes on systems whose small vibrations are known: a fixed-free chain of
// springs written as a split first-order system with nonlinear terms that vanish at rest (its
// frequencies are those of the symmetric matrix M^-1/2 D^T K D M^-1/2), and operators with a
// divergent or a flutter mode.

#include "numerics/RestModes.hpp"
#include "solvers/DenseEigenproblems.hpp"

#include "core/Error.hpp"

#include <gtest/gtest.h>

#include <Eigen/Core>

#include <cmath>
#include <complex>
#include <vector>

using namespace mfwave;

namespace {

// q = spring extensions e_j (spring j joins mass j - 1, the wall for j = 0, and mass j),
// p = [velocities v_j; a bookkeeping entry s = sum e_j^2 / 2 that is not a velocity]:
//   e_j' = v_j - v_{j-1} + e_j^2,   m_j v_j' = -k_j e_j + k_{j+1} e_{j+1} - e_j^3,   s' = sum e_j v_j.
class SpringChain : public SplitFirstOrderSystem {
 public:
  SpringChain(std::vector<Real> masses, std::vector<Real> stiffnesses) : m_(std::move(masses)), k_(std::move(stiffnesses)) {}
  Index count() const { return static_cast<Index>(m_.size()); }
  Index size() const override { return 2 * count() + 1; }
  Index configurationSize() const override { return count(); }
  void configurationRate(Real, Eigen::Ref<const Vector> y, Eigen::Ref<Vector> qdot) override {
    for (Index j = 0; j < count(); ++j) {
      const Real left = j > 0 ? y[count() + j - 1] : 0.0;
      qdot[j] = y[count() + j] - left + y[j] * y[j];
    }
  }
  void momentumRate(Real, Eigen::Ref<const Vector> y, Eigen::Ref<Vector> pdot) override {
    Real power = 0;
    for (Index j = 0; j < count(); ++j) {
      const auto s = static_cast<std::size_t>(j);
      const Real next = j + 1 < count() ? k_[s + 1] * y[j + 1] : 0.0;
      pdot[j] = (-k_[s] * y[j] + next - y[j] * y[j] * y[j]) / m_[s];
      power += y[j] * y[count() + j];
    }
    pdot[count()] = power;
  }
  // The frequencies of the linear chain: eigenvalues of M^-1/2 D^T K D M^-1/2 (D the difference
  // matrix with the wall), square-rooted, ascending.
  std::vector<Real> exactFrequencies() const {
    const Index n = count();
    Eigen::MatrixXd D = Eigen::MatrixXd::Zero(n, n), K = Eigen::MatrixXd::Zero(n, n), S(n, n);
    for (Index j = 0; j < n; ++j) {
      D(j, j) = 1;
      if (j > 0) D(j, j - 1) = -1;
      K(j, j) = k_[static_cast<std::size_t>(j)];
    }
    const Eigen::MatrixXd stiffness = D.transpose() * K * D;
    for (Index a = 0; a < n; ++a)
      for (Index b = 0; b < n; ++b)
        S(a, b) = stiffness(a, b) / std::sqrt(m_[static_cast<std::size_t>(a)] * m_[static_cast<std::size_t>(b)]);
    const Eigen::VectorXd omega2 = symmetricEigenvalues(S);
    std::vector<Real> w;
    for (Index k = 0; k < n; ++k) w.push_back(std::sqrt(omega2[k]));
    return w;
  }

 private:
  std::vector<Real> m_, k_;
};

// The entries of y that are the chain's velocities.
std::vector<Index> velocityEntries(const SpringChain& chain) {
  std::vector<Index> velocities;
  for (Index j = 0; j < chain.count(); ++j) velocities.push_back(chain.count() + j);
  return velocities;
}

}  // namespace

TEST(RestModes, SpringChainFrequenciesMatchTheSymmetricEigenproblem) {
  SpringChain chain({1.0, 2.0, 0.5, 1.5, 1.0, 3.0}, {4.0, 1.0, 2.5, 3.0, 0.7, 2.0});
  const Eigen::MatrixXd A = restOperator(chain, 0, Vector::Zero(chain.size()), velocityEntries(chain));
  // A = -M^-1 D^T K D, entry by entry (the chain's coupling of v_2 to v_1's acceleration: k_2 / m_1).
  EXPECT_NEAR(A(0, 0), -(4.0 + 1.0) / 1.0, 1e-7);
  EXPECT_NEAR(A(0, 1), 1.0 / 1.0, 1e-7);
  const RestModes modes = restModes(A);
  const std::vector<Real> exact = chain.exactFrequencies();
  ASSERT_EQ(modes.frequencies.size(), exact.size());
  for (std::size_t k = 0; k < exact.size(); ++k) EXPECT_NEAR(modes.frequencies[k], exact[k], 1e-7 * exact.back()) << k;
  EXPECT_EQ(modes.largestGrowthRate, 0);
  EXPECT_EQ(modes.zeroModes, 0);
}

TEST(RestModes, DivergentAndFlutterModesShowAsGrowth) {
  Eigen::MatrixXd divergent(2, 2);
  divergent << -4, 0, 0, 9;  // omega = 2, and a mode growing like exp(3 t)
  RestModes modes = restModes(divergent);
  ASSERT_EQ(modes.frequencies.size(), 1u);
  EXPECT_NEAR(modes.frequencies[0], 2, 1e-12);
  EXPECT_NEAR(modes.largestGrowthRate, 3, 1e-12);

  Eigen::MatrixXd flutter(2, 2);
  flutter << -1, 2, -2, -1;  // lambda = -1 +- 2i: s = sqrt(lambda) has real part 0.786
  modes = restModes(flutter);
  EXPECT_NEAR(modes.largestGrowthRate, std::sqrt(std::complex<Real>(-1, 2)).real(), 1e-12);

  Eigen::MatrixXd withNullMode = Eigen::MatrixXd::Zero(3, 3);
  withNullMode(0, 0) = -1;
  withNullMode(1, 1) = -16;
  modes = restModes(withNullMode);
  EXPECT_EQ(modes.zeroModes, 1);
  ASSERT_EQ(modes.frequencies.size(), 2u);
  EXPECT_NEAR(modes.frequencies[1], 4, 1e-12);
}

TEST(RestModes, ProductsAlongDirectionsAreSumsOfColumns) {
  // A d for a direction moving several masses at once (as a periodic site and its copies move in
  // the jittered clouds) equals the same combination of A's columns, read at any rows.
  SpringChain chain({1.0, 2.0, 0.5, 1.5, 1.0, 3.0}, {4.0, 1.0, 2.5, 3.0, 0.7, 2.0});
  const std::vector<Index> velocities = velocityEntries(chain);
  const Vector rest = Vector::Zero(chain.size());
  const Eigen::MatrixXd A = restOperator(chain, 0, rest, velocities);
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(6, 3);
  dense(0, 0) = dense(3, 0) = 1;                      // masses 0 and 3 together
  dense(2, 1) = 1;                                    // one column
  for (Index j = 0; j < 6; ++j) dense(j, 2) = 0.5 * static_cast<Real>(j * j);  // a smooth field
  const SparseMatrix directions = dense.sparseView();
  const std::vector<Index> rows = {5, 1, 2};
  const Eigen::MatrixXd products = restOperatorProducts(chain, 0, rest, velocities, directions, rows);
  ASSERT_EQ(products.rows(), 3);
  ASSERT_EQ(products.cols(), 3);
  const Eigen::MatrixXd expected = A * dense;
  for (std::size_t r = 0; r < rows.size(); ++r)
    for (Index j = 0; j < 3; ++j)
      EXPECT_NEAR(products(static_cast<Index>(r), j), expected(rows[r], j), 1e-6 * (1 + std::abs(expected(rows[r], j))))
          << r << ", " << j;
  EXPECT_THROW(restOperatorProducts(chain, 0, rest, velocities, SparseMatrix(5, 1), rows), InputError);
  EXPECT_THROW(restOperatorProducts(chain, 0, rest, velocities, directions, {6}), InputError);
}

TEST(RestModes, BadArgumentsAreRejected) {
  SpringChain chain({1.0, 1.0}, {1.0, 1.0});
  const Vector rest = Vector::Zero(chain.size());
  EXPECT_THROW(restOperator(chain, 0, rest, {0}), InputError);  // an entry of q
  EXPECT_THROW(restOperator(chain, 0, rest, {5}), InputError);  // beyond y
  EXPECT_THROW(restOperator(chain, 0, Vector::Zero(3), {2}), InputError);
  EXPECT_THROW(restOperator(chain, 0, rest, {2}, 0.0), InputError);
}
