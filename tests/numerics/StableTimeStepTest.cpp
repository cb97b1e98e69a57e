#include "numerics/StableTimeStep.hpp"
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

namespace {

// u'' = f - K u with K = M^{-1} K of the spring chain and a constant load f: the acceleration alone
// must give the chain's omega_max^2, the load removed.
class LoadedChain : public SecondOrderSystem {
 public:
  LoadedChain(int n, Real m, Real k) : system_(chain(n, m, k)), load_(Vector::Constant(n, 3.0)) {}
  Index size() const override { return system_.size(); }
  bool dependsOnVelocity() const override { return false; }
  void acceleration(Real t, Eigen::Ref<const Vector> u, Eigen::Ref<const Vector> v, Eigen::Ref<Vector> a) override {
    system_.acceleration(t, u, v, a);
    a += load_;
  }

 private:
  LinearSecondOrderSystem system_;
  Vector load_;
};

}  // namespace

TEST(AccelerationSpectralRadius, FindsTheLargestEigenvalueFromTheAccelerationAlone) {
  const int n = 12;
  const Real m = 2, k = 50;
  const Real exact = 4 * k / m * std::pow(std::sin(n * M_PI / (2 * (n + 1.0))), 2);
  LoadedChain system(n, m, k);
  const AccelerationSpectralRadius radius = accelerationSpectralRadius(system, 0.5, 1e-10, 20000);
  EXPECT_TRUE(radius.converged);
  EXPECT_NEAR(radius.value, exact, 1e-6 * exact);
  EXPECT_GT(radius.iterations, 20);
  // Cut short, it says so and gives its last ratio, from below.
  const AccelerationSpectralRadius early = accelerationSpectralRadius(system, 0.5, 1e-14, 30);
  EXPECT_FALSE(early.converged);
  EXPECT_EQ(early.iterations, 30);
  EXPECT_LE(early.value, exact * (1 + 1e-12));
  EXPECT_GT(early.value, 0.5 * exact);
}
