// The matrix-free periodic system (lib/lattice/PeriodicStencilSystem through periodicStencilSystem)
// against the assembled periodic matrix it replaces: the same products to round-off in 1-, 2- and
// 3-D, scalar and vector, with stencils that wrap across every face; bitwise the same on 1 and 2
// threads; the energies and row sums the observers read; the planewave study's wave stepped on it.

#include "numerics/PeriodicLattice.hpp"
#include "lattice/PeriodicStencilSystem.hpp"
#include "core/Error.hpp"
#include "support/RandomVector.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <cstring>
#include <random>

using namespace mfwave;

namespace {

// Every offset within `reach` steps along each axis, with random blocks: a stencil denser than any
// method's, so that every neighbouring line and both line ends wrap.
template <int D>
LatticeStencil<D> randomStencil(int components, int reach, Real dx, unsigned seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<Real> uniform(-1, 1);
  LatticeStencil<D> stencil;
  stencil.components = components;
  const int width = 2 * reach + 1;
  int count = 1;
  for (int d = 0; d < D; ++d) count *= width;
  for (int k = 0; k < count; ++k) {
    Vec<D> r;
    int rest = k;
    for (int d = 0; d < D; ++d) {
      r(d) = dx * (rest % width - reach);
      rest /= width;
    }
    Eigen::MatrixXd block(components, components);
    for (int p = 0; p < components; ++p)
      for (int q = 0; q < components; ++q) block(p, q) = uniform(random);
    stencil.offsets.push_back(r);
    stencil.blocks.push_back(block);
  }
  return stencil;
}

template <int D>
void expectSameProducts(int components, int reach, int cells) {
  const Real dx = 0.1;
  const auto op = makePeriodicLatticeOperator<D>(randomStencil<D>(components, reach, dx, 7u + components), dx, cells);
  const SparseMatrix a = periodicMatrix(op.acceleration, dx, cells);
  const auto system = periodicStencilSystem(op);
  ASSERT_EQ(system->size(), op.size());
  const Vector u = test::randomVector(op.size(), 11);
  const Vector expected = a * u;
  Vector got(op.size());
  system->acceleration(0, u, u, got);
  const Real scale = expected.cwiseAbs().maxCoeff();
  EXPECT_LT((got - expected).cwiseAbs().maxCoeff(), 1e-13 * scale)
      << D << "-D, " << components << " components, reach " << reach << ", " << cells << " cells";

  // K = -A, the energies and the Gershgorin sums the stable step and the ledger read.
  Vector ku;
  system->applyStiffness(u, ku);
  EXPECT_LT((ku + expected).cwiseAbs().maxCoeff(), 1e-13 * scale);
  EXPECT_NEAR(system->strainEnergy(u), -0.5 * u.dot(expected), 1e-12 * std::abs(u.dot(expected)));
  EXPECT_DOUBLE_EQ(system->kineticEnergy(u), 0.5 * u.squaredNorm());
  const Vector sums = system->stiffnessAbsoluteRowSums();
  for (Index i = 0; i < op.size(); ++i) EXPECT_NEAR(sums[i], a.row(i).cwiseAbs().sum(), 1e-13 * sums[i]);
  EXPECT_EQ(system->lumpedMass(), Vector::Ones(op.size()));
}

}  // namespace

TEST(PeriodicStencilSystem, GivesTheAssembledPeriodicProductsInEveryDimension) {
  expectSameProducts<1>(1, 2, 6);
  expectSameProducts<1>(1, 1, 64);
  expectSameProducts<2>(1, 2, 6);
  expectSameProducts<2>(2, 2, 10);
  expectSameProducts<2>(2, 1, 32);
  expectSameProducts<3>(1, 1, 4);
  expectSameProducts<3>(3, 1, 6);
  expectSameProducts<3>(3, 2, 12);
}

TEST(PeriodicStencilSystem, IsBitwiseTheSameOnOneAndTwoThreads) {
  const Real dx = 0.1;
  const auto op = makePeriodicLatticeOperator<3>(randomStencil<3>(3, 2, dx, 3), dx, 48);
  const auto system = periodicStencilSystem(op);
  const Vector u = test::randomVector(op.size(), 5);
  Vector one(op.size()), two(op.size());
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  system->acceleration(0, u, u, one);
  omp_set_num_threads(2);
  system->acceleration(0, u, u, two);
  omp_set_num_threads(threads);
  EXPECT_EQ(std::memcmp(one.data(), two.data(), sizeof(Real) * static_cast<std::size_t>(one.size())), 0);
}

TEST(PeriodicStencilSystem, ASecondStencilOfTheSameShapeIsNotServedTheFirstsTerms) {
  // stencilRun keeps a thread's last stencil's terms; a new table of the same shape (often at the
  // address the last one freed) must bring its own.
  const Real dx = 0.1;
  for (unsigned seed = 1; seed <= 3; ++seed) {
    const auto op = makePeriodicLatticeOperator<2>(randomStencil<2>(2, 1, dx, seed), dx, 32);
    const Vector u = test::randomVector(op.size(), seed);
    const Vector expected = periodicMatrix(op.acceleration, dx, 32) * u;
    Vector got(op.size());
    periodicStencilSystem(op)->acceleration(0, u, u, got);
    EXPECT_LT((got - expected).cwiseAbs().maxCoeff(), 1e-13 * expected.cwiseAbs().maxCoeff()) << seed;
  }
}

TEST(PeriodicStencilSystem, RefusesAConsistentMassAndStencilsItCannotWrap) {
  const Real dx = 0.1;
  auto stencil = randomStencil<2>(2, 1, dx, 1);
  const auto consistent = makePeriodicLatticeOperator<2>(stencil, dx, 8, randomStencil<2>(2, 1, dx, 2));
  try {
    periodicStencilSystem(consistent);
    FAIL() << "a consistent mass was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "mass");
  }
  try {
    PeriodicStencilSystem<2, 2>(4, {{0, 0}, {2, 0}}, std::vector<Real>(8, 1.0));
    FAIL() << "a stencil reaching half the lattice was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "cells");
  }
  try {
    PeriodicStencilSystem<2, 2>(8, {{0, 0}, {0, 0}}, std::vector<Real>(8, 1.0));
    FAIL() << "an offset given twice was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "stencil");
  }
  try {
    PeriodicStencilSystem<2, 2>(8, {{0, 0}}, std::vector<Real>(3, 1.0));
    FAIL() << "blocks of the wrong size were accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "stencil");
  }
}
