#include "core/Error.hpp"
#include "core/TimeFunction.hpp"
#include "methods/finite_difference/FiniteDifferenceLattice.hpp"
#include "neighbours/CellList.hpp"
#include "neighbours/NeighbourList.hpp"
#include "particles/BoxFace.hpp"
#include "particles/Lattice.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace mfwave;

namespace {

FiniteDifferenceWaveOptions options(Real dx, std::uint8_t fixedFaces) {
  FiniteDifferenceWaveOptions o;
  o.spacing = dx;
  o.density = 2;
  o.modulus = 3;
  o.fixedFaces = fixedFaces;
  return o;
}

// The lattice stencils against the sparse assembly on the whole lattice: the same matrices, and
// the same acceleration and energies of a rough state.
template <int D>
void expectSameAsSparse(const std::array<Index, D>& nodes, std::uint8_t fixedFaces) {
  const Real dx = 0.1;
  Vec<D> upper;
  for (int a = 0; a < D; ++a) upper[a] = static_cast<Real>(nodes[static_cast<std::size_t>(a)] - 1) * dx;
  const ParticleSet<D> particles = makeLattice<D>(Vec<D>::Zero(), upper, dx);
  LinearSecondOrderSystem sparse = assembleFiniteDifferenceWave<D>(
      particles, buildNeighbourList(CellList<D>(particles, 1.5 * dx)), options(dx, fixedFaces));
  const Index n = particles.size();
  const TimeFunction two = TimeFunction::constant(2.0);
  SparseLoad load{{n / 2, n / 3}, {1.5, -0.5}, &two};
  LatticeSecondOrderSystem<D, 1> lattice = finiteDifferenceLatticeSystem<D>(nodes, options(dx, fixedFaces), {load});
  ASSERT_EQ(lattice.size(), n);
  EXPECT_EQ(lattice.stiffness().mismatch(sparse.stiffness()), 0);
  EXPECT_EQ(lattice.mass().mismatch(sparse.mass()), 0);
  EXPECT_LE(lattice.stiffness().typeCount(), static_cast<Index>(std::pow(5, D)));  // depth 2: 5 row types per axis

  Vector u(n), v(n);
  for (Index i = 0; i < n; ++i) {
    u[i] = std::sin(1.7 * static_cast<Real>(i)) + 0.3;
    v[i] = std::cos(0.9 * static_cast<Real>(i));
  }
  Vector a(n), expected(n), f(n);
  lattice.acceleration(0.0, u, v, a);
  sparse.applyStiffness(u, expected);
  f.setZero();
  f[n / 2] += 3.0;
  f[n / 3] -= 1.0;
  const Vector m = sparse.lumpedMass();
  for (Index i = 0; i < n; ++i) EXPECT_NEAR(a[i], (f[i] - expected[i]) / m[i], 1e-12 * (1 + std::abs(a[i]))) << i;
  EXPECT_NEAR(lattice.strainEnergy(u), sparse.strainEnergy(u), 1e-12 * sparse.strainEnergy(u));
  EXPECT_NEAR(lattice.kineticEnergy(v), sparse.kineticEnergy(v), 1e-12 * sparse.kineticEnergy(v));
}

}  // namespace

TEST(FiniteDifferenceLattice, LineWithFixedEndsIsTheSparseOperator) {
  expectSameAsSparse<1>({41}, faceBit(BoxFace::MinusX) | faceBit(BoxFace::PlusX));
}

TEST(FiniteDifferenceLattice, RectangleWithFixedFacesIsTheSparseOperator) {
  expectSameAsSparse<2>({13, 9}, allFaces(2));
}

TEST(FiniteDifferenceLattice, BlockWithFixedFacesIsTheSparseOperator) {
  expectSameAsSparse<3>({9, 7, 6}, allFaces(3));
}

TEST(FiniteDifferenceLattice, AFreeFaceIsRefusedAsTheSparseAssemblyRefusesIt) {
  try {
    finiteDifferenceLatticeSystem<2>({10, 10}, options(0.1, faceBit(BoxFace::MinusX) | faceBit(BoxFace::PlusX)));
    FAIL() << "a free face was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "boundary");
  }
}
