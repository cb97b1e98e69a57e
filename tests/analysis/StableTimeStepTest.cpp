#include "analysis/StableTimeStep.hpp"
#include "systems/LinearSecondOrderSystem.hpp"
#include "core/Error.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace mfwave;

namespace {

// Fixed-fixed spring chain of n masses m with springs k: omega_max^2 = (4 k / m) sin^2(n pi / (2(n+1))).
LinearSecondOrderSystem chain(int n, Real m, Real k) {
  SparseMatrix mass(n, n), stiffness(n, n);
  std::vector<Triplet> t;
  for (int i = 0; i < n; ++i) {
    mass.insert(i, i) = m;
    t.emplace_back(i, i, 2 * k);
    if (i > 0) t.emplace_back(i, i - 1, -k);
    if (i + 1 < n) t.emplace_back(i, i + 1, -k);
  }
  stiffness.setFromTriplets(t.begin(), t.end());
  return LinearSecondOrderSystem(mass, SparseMatrix(), stiffness);
}

}  // namespace

TEST(StableTimeStep, MatchesTheSpringChainsClosedForm) {
  const int n = 40;
  const Real m = 2, k = 50;
  const Real exact = 4 * k / m * std::pow(std::sin(n * M_PI / (2 * (n + 1.0))), 2);
  const StableTimeStep step = centralDifferenceStableStep(chain(n, m, k), 1e-10, 200000);
  EXPECT_TRUE(step.converged);
  EXPECT_NEAR(step.powerIterationOmegaSquared, exact, 1e-4 * exact);
  EXPECT_LE(step.powerIterationOmegaSquared, exact * (1 + 1e-12));  // a Rayleigh quotient: from below
  EXPECT_DOUBLE_EQ(step.gershgorinOmegaSquared, 4 * k / m);          // the bound, above
  EXPECT_GE(step.estimate(), step.safe());
  EXPECT_NEAR(step.estimate(), 2 / std::sqrt(exact), 1e-4 * 2 / std::sqrt(exact));
  EXPECT_DOUBLE_EQ(centralDifferenceSafeStep(chain(n, m, k)), step.safe());
}

TEST(StableTimeStep, RejectsAConsistentMass) {
  SparseMatrix m(2, 2), k(2, 2);
  m.insert(0, 0) = 2;
  m.insert(0, 1) = 1;
  m.insert(1, 0) = 1;
  m.insert(1, 1) = 2;
  k.insert(0, 0) = 1;
  k.insert(1, 1) = 1;
  EXPECT_THROW(centralDifferenceStableStep(LinearSecondOrderSystem(m, SparseMatrix(), k)), InputError);
}
