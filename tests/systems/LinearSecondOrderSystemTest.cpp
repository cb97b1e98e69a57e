#include "core/Error.hpp"
#include "systems/LinearSecondOrderSystem.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <random>
#include <vector>

using namespace mfwave;

namespace {

SparseMatrix diagonal(const std::vector<Real>& d) {
  SparseMatrix m(static_cast<int>(d.size()), static_cast<int>(d.size()));
  for (size_t i = 0; i < d.size(); ++i) m.insert(static_cast<int>(i), static_cast<int>(i)) = d[i];
  return m;
}

SparseMatrix twoByTwo(Real a00, Real a01, Real a10, Real a11) {
  SparseMatrix m(2, 2);
  m.insert(0, 0) = a00;
  m.insert(0, 1) = a01;
  m.insert(1, 0) = a10;
  m.insert(1, 1) = a11;
  return m;
}

}  // namespace

TEST(LinearSecondOrderSystem, AccelerationIsInverseMassTimesResidual) {
  // Two masses on springs: M = diag(2, 4), K = [[3, -1], [-1, 2]], C = diag(0.5, 0), f = (t, 1).
  LinearSecondOrderSystem system(diagonal({2, 4}), diagonal({0.5, 0}), twoByTwo(3, -1, -1, 2), [](Real t, Vector& f) {
    f[0] = t;
    f[1] = 1;
  });
  Vector u(2), v(2), a(2);
  u << 1, 2;
  v << 3, 4;
  system.acceleration(0.5, u, v, a);
  EXPECT_NEAR(a[0], (0.5 - (3 * 1 - 1 * 2) - 0.5 * 3) / 2, 1e-15);
  EXPECT_NEAR(a[1], (1 - (-1 * 1 + 2 * 2)) / 4.0, 1e-15);
  EXPECT_TRUE(system.dependsOnVelocity());
  EXPECT_NEAR(system.kineticEnergy(v), 0.5 * (2 * 9 + 4 * 16), 1e-14);
  EXPECT_NEAR(system.strainEnergy(u), 0.5 * (3 - 2 - 2 + 8), 1e-14);
}

TEST(LinearSecondOrderSystem, UndampedWithoutForceDoesNotDependOnVelocity) {
  LinearSecondOrderSystem system(diagonal({1}), SparseMatrix(), diagonal({4}));
  EXPECT_FALSE(system.dependsOnVelocity());
  Vector u(1), v(1), a(1);
  u << 0.5;
  v << 100;
  system.acceleration(0, u, v, a);
  EXPECT_DOUBLE_EQ(a[0], -2.0);
}

TEST(LinearSecondOrderSystem, LoadsAttachedLaterDriveTheAcceleration) {
  LinearSecondOrderSystem system(diagonal({2, 4}), SparseMatrix(), diagonal({1, 1}));
  system.setForce([](Real t, Vector& f) { f[1] = 8 * t; });
  Vector u = Vector::Zero(2), v = Vector::Zero(2), a(2);
  system.acceleration(0.5, u, v, a);
  EXPECT_DOUBLE_EQ(a[0], 0);
  EXPECT_DOUBLE_EQ(a[1], 1);
}

TEST(LinearSecondOrderSystem, ConsistentMassIsSolvedForExplicitUse) {
  // M = [[2, 1], [1, 2]], K = I, f = 0, u = (1, 2): M a = -u gives a = (0, -1).
  LinearSecondOrderSystem system(twoByTwo(2, 1, 1, 2), SparseMatrix(), diagonal({1, 1}));
  Vector u(2), v = Vector::Zero(2), a(2);
  u << 1, 2;
  system.acceleration(0, u, v, a);
  EXPECT_NEAR(a[0], 0.0, 1e-15);
  EXPECT_NEAR(a[1], -1.0, 1e-15);
  // A copy shares the factorisation and gives the same.
  LinearSecondOrderSystem copy = system;
  Vector b(2);
  copy.acceleration(0, u, v, b);
  EXPECT_EQ(a, b);
  // solveMass uses the same factorisation: M^-1 (-u) is that acceleration, bitwise.
  EXPECT_EQ(system.solveMass(-u), a);
  // Lumped: entry-wise.
  LinearSecondOrderSystem lumped(diagonal({2, 4}), SparseMatrix(), diagonal({1, 1}));
  EXPECT_EQ(lumped.solveMass(u), Vector(Eigen::Vector2d(0.5, 0.5)));
  EXPECT_THROW(lumped.solveMass(Vector::Zero(3)), InputError);
}

TEST(LinearSecondOrderSystem, AMassThatCannotBeInvertedIsRefusedOnFirstExplicitUse) {
  // A lumped mass with a zero entry: bad input naming the mass.
  LinearSecondOrderSystem lumped(diagonal({1, 0}), SparseMatrix(), diagonal({1, 1}));
  Vector u = Vector::Zero(2), v = Vector::Zero(2), a(2);
  EXPECT_THROW(lumped.acceleration(0, u, v, a), InputError);
  // A singular consistent mass: the factorisation says so.
  LinearSecondOrderSystem singular(twoByTwo(1, 1, 1, 1), SparseMatrix(), diagonal({1, 1}));
  EXPECT_THROW(singular.acceleration(0, u, v, a), Error);
}

TEST(LinearSecondOrderSystem, MismatchedSizesNameTheMatrix) {
  try {
    LinearSecondOrderSystem system(diagonal({1, 1, 1}), SparseMatrix(), diagonal({1, 1}));
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "mass");
  }
}

TEST(LinearSecondOrderSystem, DampingAttachedLaterActsOnTheVelocity) {
  LinearSecondOrderSystem system(diagonal({2, 4}), SparseMatrix(), diagonal({1, 1}));
  EXPECT_FALSE(system.dependsOnVelocity());
  system.setDamping(diagonal({6, 0}));
  EXPECT_TRUE(system.dependsOnVelocity());
  Vector u = Vector::Zero(2), v(2), a(2);
  v << 1, 5;
  system.acceleration(0, u, v, a);
  EXPECT_DOUBLE_EQ(a[0], -3);
  EXPECT_DOUBLE_EQ(a[1], 0);
  try {
    system.setDamping(diagonal({1, 1, 1}));
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "damping");
  }
}

TEST(LinearSecondOrderSystem, AccelerationIsBitwiseTheSameOnOneAndTwoThreads) {
  // A random sparse K large enough (2e5 entries) for the parallel row loop, against Eigen's product.
  const Index n = 20000;
  std::mt19937 random(7);
  std::uniform_real_distribution<Real> value(-1, 1);
  std::uniform_int_distribution<Index> column(0, n - 1);
  std::vector<Eigen::Triplet<Real>> entries;
  for (Index r = 0; r < n; ++r)
    for (int k = 0; k < 11; ++k) entries.emplace_back(r, column(random), value(random));
  SparseMatrix K(n, n), M(n, n);
  K.setFromTriplets(entries.begin(), entries.end());
  M.setIdentity();
  Vector u(n), v = Vector::Zero(n);
  for (Index i = 0; i < n; ++i) u(i) = value(random);
  LinearSecondOrderSystem system(M, SparseMatrix(), K);
  Vector one(n), two(n);
  omp_set_num_threads(1);
  system.acceleration(0, u, v, one);
  omp_set_num_threads(2);
  system.acceleration(0, u, v, two);
  EXPECT_EQ((one - two).cwiseAbs().maxCoeff(), 0.0);
  const Vector reference = -(K * u);
  EXPECT_LT((one - reference).cwiseAbs().maxCoeff(), 1e-13);
}
