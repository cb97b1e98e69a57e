// lowestModes against closed forms: the free-free chain (one rigid mode, lambda_k = (2 - 2 cos(k pi
// / n)) / m), its multiplicity kept for two uncoupled chains, and an indefinite matrix refused by the
// factorisation.
#include "numerics/LowestModes.hpp"

#include "core/Error.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace mfwave {
namespace {

// Free-free chain of n unit springs between n masses: K = tridiag(-1, 2, -1) with 1 at both ends,
// `copies` uncoupled copies one after another.
SparseMatrix springChain(Index n, int copies) {
  std::vector<Eigen::Triplet<Real>> entries;
  for (int c = 0; c < copies; ++c) {
    const Index o = c * n;
    for (Index i = 0; i + 1 < n; ++i) {
      entries.emplace_back(o + i, o + i, 1.0);
      entries.emplace_back(o + i + 1, o + i + 1, 1.0);
      entries.emplace_back(o + i, o + i + 1, -1.0);
      entries.emplace_back(o + i + 1, o + i, -1.0);
    }
  }
  SparseMatrix k(n * copies, n * copies);
  k.setFromTriplets(entries.begin(), entries.end());
  return k;
}

TEST(LowestModes, FreeChainGivesItsRigidModeAndTheClosedFormFrequencies) {
  const Index n = 200;
  const Real m = 0.5;
  const LowestModes modes = lowestModes(springChain(n, 1), Vector::Constant(n, m), 5, 1e-10);
  ASSERT_TRUE(modes.shiftedMatrixPositiveDefinite);
  ASSERT_TRUE(modes.converged);
  for (int k = 0; k < 5; ++k) {
    const Real exact = (2 - 2 * std::cos(k * M_PI / n)) / m;
    EXPECT_NEAR(modes.eigenvalues[static_cast<std::size_t>(k)], exact, 1e-9 * 4 / m) << k;
    EXPECT_LT(modes.residuals[static_cast<std::size_t>(k)], 1e-8);
  }
}

TEST(LowestModes, KeepsTheMultiplicityOfRepeatedEigenvalues) {
  const Index n = 50;
  const LowestModes modes = lowestModes(springChain(n, 3), Vector::Ones(3 * n), 6, 1e-10);
  ASSERT_TRUE(modes.converged);
  const Real first = 2 - 2 * std::cos(M_PI / n);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(modes.eigenvalues[static_cast<std::size_t>(k)], 0.0, 1e-9) << k;
  for (int k = 3; k < 6; ++k) EXPECT_NEAR(modes.eigenvalues[static_cast<std::size_t>(k)], first, 1e-9) << k;
}

TEST(LowestModes, ANegativeEigenvalueBelowTheShiftFailsTheFactorisation) {
  const Index n = 40;
  SparseMatrix k = springChain(n, 1);
  k.coeffRef(7, 7) = -1.0;  // e_7^T K e_7 < 0: K is indefinite
  const LowestModes modes = lowestModes(k, Vector::Ones(n), 3, 1e-6);
  EXPECT_FALSE(modes.shiftedMatrixPositiveDefinite);
  EXPECT_TRUE(modes.eigenvalues.empty());
  EXPECT_THROW(lowestModes(k, Vector::Ones(n), 0, 1e-6), InputError);
  EXPECT_THROW(lowestModes(k, -Vector::Ones(n), 3, 1e-6), InputError);
}

}  // namespace
}  // namespace mfwave
