// The lattice system against the sparse system of the same matrices: acceleration, the dashpot
// solve of central difference with prescribed dofs, energies, the lumped mass; and what it refuses.

#include "core/Error.hpp"
#include "lattice/LatticeSecondOrderSystem.hpp"
#include "systems/LinearSecondOrderSystem.hpp"

#include "support/RandomVector.hpp"

#include <gtest/gtest.h>

#include <random>

namespace mfwave {
namespace {

constexpr Index kNodes = 30;
const std::array<Index, 2> kShape{kNodes, 1};  // 2 components per node: a 2-D lattice one node high

// On a lattice of n nodes: the stiffness (a 3-point stencil coupling the components, stiffer at the
// faces), the lumped mass (lighter at the faces), dashpots on the last node only (a full 2 x 2 block).
SparseMatrix stiffness(Index n) {
  std::vector<Triplet> t;
  for (Index i = 0; i < n; ++i)
    for (int c = 0; c < 2; ++c) {
      const int row = static_cast<int>(2 * i + c);
      const Real face = (i == 0 || i == n - 1) ? 1.5 : 1.0;
      t.emplace_back(row, row, 2.0 * face + c);
      t.emplace_back(row, static_cast<int>(2 * i + 1 - c), 0.25);
      if (i > 0) t.emplace_back(row, static_cast<int>(2 * (i - 1) + c), -1.0);
      if (i + 1 < n) t.emplace_back(row, static_cast<int>(2 * (i + 1) + c), -1.0);
    }
  SparseMatrix m(2 * n, 2 * n);
  m.setFromTriplets(t.begin(), t.end());
  return m;
}
SparseMatrix mass(Index n) {
  std::vector<Triplet> t;
  for (Index i = 0; i < n; ++i)
    for (int c = 0; c < 2; ++c) t.emplace_back(static_cast<int>(2 * i + c), static_cast<int>(2 * i + c), (i == 0 || i == n - 1) ? 0.5 : 1.0);
  SparseMatrix m(2 * n, 2 * n);
  m.setFromTriplets(t.begin(), t.end());
  return m;
}
// Dashpots that couple the last two nodes (as through a traction sum), symmetric positive definite.
SparseMatrix coupledDashpots(Index n) {
  const int a = static_cast<int>(2 * (n - 2));
  std::vector<Triplet> t;
  for (int i = 0; i < 4; ++i) {
    t.emplace_back(a + i, a + i, 3.0);
    if (i + 1 < 4) {
      t.emplace_back(a + i, a + i + 1, 0.7);
      t.emplace_back(a + i + 1, a + i, 0.7);
    }
  }
  SparseMatrix m(2 * n, 2 * n);
  m.setFromTriplets(t.begin(), t.end());
  return m;
}

SparseMatrix dashpots(Index n) {
  const int a = static_cast<int>(2 * (n - 1));
  std::vector<Triplet> t{{a, a, 3.0}, {a, a + 1, 0.5}, {a + 1, a, 0.5}, {a + 1, a + 1, 2.0}};
  SparseMatrix m(2 * n, 2 * n);
  m.setFromTriplets(t.begin(), t.end());
  return m;
}

using test::randomVector;

struct Pair {
  LinearSecondOrderSystem sparse;
  LatticeSecondOrderSystem<2> lattice;
};

Pair systems() {
  const LatticeRowTypes<2> types(kShape, 1);
  const Index m = types.compactNodes()[0];
  auto force = [](Real t, Index dof) { return std::sin(t) * (dof == 3 ? 2.0 : 0.0); };
  LinearSecondOrderSystem sparse(mass(kNodes), dashpots(kNodes), stiffness(kNodes), [force](Real t, Vector& f) {
    f[3] += force(t, 3);
  });
  LatticeSecondOrderSystem<2> lattice(LatticeStencils<2>(types, mass(m)), LatticeStencils<2>(types, dashpots(m)),
                                      LatticeStencils<2>(types, stiffness(m)),
                                      [force](Real t, Eigen::Ref<Vector> f) { f[3] += force(t, 3); });
  return {std::move(sparse), std::move(lattice)};
}

TEST(LatticeSecondOrderSystem, MatchesTheSparseSystemOfTheSameMatrices) {
  Pair s = systems();
  ASSERT_EQ(s.lattice.size(), s.sparse.size());
  EXPECT_TRUE(s.lattice.hasDamping());
  const Vector u = randomVector(s.sparse.size(), 1), v = randomVector(s.sparse.size(), 2);
  Vector a(u.size()), b(u.size());
  s.sparse.acceleration(0.4, u, v, a);
  s.lattice.acceleration(0.4, u, v, b);
  EXPECT_LE((a - b).cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_NEAR(s.lattice.kineticEnergy(v), s.sparse.kineticEnergy(v), 1e-13);
  EXPECT_NEAR(s.lattice.strainEnergy(u), s.sparse.strainEnergy(u), 1e-13);
  EXPECT_NEAR(s.lattice.dampingPower(v), s.sparse.dampingPower(v), 1e-13);
  EXPECT_EQ(s.lattice.lumpedMass(), s.sparse.lumpedMass());
  // the dashpot solve with a prescribed dof on the damped node: its other dof is re-solved
  const std::vector<Index> prescribed{2 * kNodes - 2, 0};
  const Vector known = Vector::Constant(2, 0.7);
  const auto solveA = s.sparse.centredDamping(0.1, prescribed);
  const auto solveB = s.lattice.centredDamping(0.1, prescribed);
  solveA->acceleration(0.4, u, v, known, a);
  solveB->acceleration(0.4, u, v, known, b);
  EXPECT_LE((a - b).cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_EQ(b[2 * kNodes - 2], 0.7);
  EXPECT_EQ(b[0], 0.7);
  EXPECT_GT(s.lattice.bytes(), 0u);
}

TEST(LatticeSecondOrderSystem, RefusesCoupledAndSingularMasses) {
  const LatticeRowTypes<2> types(kShape, 1);
  const Index m = types.compactNodes()[0];
  const LatticeStencils<2> k(types, stiffness(m));
  try {
    LatticeSecondOrderSystem<2>(k, LatticeStencils<2>(), k);
    FAIL() << "a coupled mass accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "mass");
  }
  SparseMatrix singular = mass(m);
  singular.coeffRef(0, 0) = 0;
  EXPECT_THROW(LatticeSecondOrderSystem<2>(LatticeStencils<2>(types, singular), LatticeStencils<2>(), k), InputError);
}

// Dashpots that couple particles: M + dt/2 C is factorised on the nodes they reach, and the solve
// with prescribed dofs there and elsewhere is the sparse system's.
TEST(LatticeSecondOrderSystem, CoupledDashpotsSolveLikeTheSparseSystem) {
  const LatticeRowTypes<2> types(kShape, 2);
  const Index m = types.compactNodes()[0];
  LinearSecondOrderSystem sparse(mass(kNodes), coupledDashpots(kNodes), stiffness(kNodes));
  LatticeSecondOrderSystem<2> lattice(LatticeStencils<2>(types, mass(m)), LatticeStencils<2>(types, coupledDashpots(m)),
                                      LatticeStencils<2>(types, stiffness(m)));
  EXPECT_FALSE(lattice.damping().blockDiagonal());
  const Vector u = randomVector(sparse.size(), 4), v = randomVector(sparse.size(), 5);
  Vector a(u.size()), b(u.size());
  sparse.acceleration(0.2, u, v, a);
  lattice.acceleration(0.2, u, v, b);
  EXPECT_LE((a - b).cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_NEAR(lattice.dampingPower(v), sparse.dampingPower(v), 1e-13);
  const std::vector<Index> prescribed{2 * kNodes - 3, 1};  // one among the coupled dofs, one far away
  const Vector known = Vector::Constant(2, -0.3);
  const auto solveA = sparse.centredDamping(0.1, prescribed);
  const auto solveB = lattice.centredDamping(0.1, prescribed);
  solveA->acceleration(0.2, u, v, known, a);
  solveB->acceleration(0.2, u, v, known, b);
  EXPECT_LE((a - b).cwiseAbs().maxCoeff(), 1e-13);
  EXPECT_EQ(b[2 * kNodes - 3], -0.3);
  EXPECT_EQ(b[1], -0.3);
}

}  // namespace
}  // namespace mfwave
