#include "core/Error.hpp"
#include "methods/finite_difference/FiniteDifferenceWaveOperator.hpp"
#include "neighbours/NeighbourList.hpp"
#include "particles/BoxFace.hpp"
#include "particles/Lattice.hpp"
#include "solvers/DenseEigenproblems.hpp"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace mfwave;

namespace {

// Sorted eigenvalues omega^2 of M^{-1} K restricted to the free (not fixed) unknowns.
template <int D>
std::vector<Real> squaredFrequencies(const ParticleSet<D>& particles, const LinearSecondOrderSystem& system,
                                     std::uint8_t fixedFaces) {
  std::vector<int> free;
  for (Index i = 0; i < particles.size(); ++i)
    if ((particles.faceMask[static_cast<std::size_t>(i)] & fixedFaces) == 0) free.push_back(static_cast<int>(i));
  const Eigen::MatrixXd k = Eigen::MatrixXd(system.stiffness());
  const Eigen::VectorXd m = Eigen::VectorXd(system.mass().diagonal());
  const int n = static_cast<int>(free.size());
  Eigen::MatrixXd a(n, n);
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c) a(r, c) = k(free[r], free[c]) / std::sqrt(m[free[r]] * m[free[c]]);
  const Eigen::VectorXd solver = symmetricEigenvalues(a);
  std::vector<Real> values(solver.data(), solver.data() + n);
  return values;
}

}  // namespace

TEST(FiniteDifferenceWaveOperator, OneDimensionalSpectrumMatchesTheClosedForm) {
  // Fixed-fixed bar of length 2 with 20 cells, rho = 2, E = 8 (c = 2):
  // omega_n = (2 c / dx) sin(n pi dx / (2 L)), n = 1..19.
  const Real length = 2, dx = 0.1, c = 2;
  const ParticleSet<1> line = makeLine(0, length, dx);
  const std::uint8_t ends = faceBit(BoxFace::MinusX) | faceBit(BoxFace::PlusX);
  FiniteDifferenceWaveOptions options;
  options.spacing = dx;
  options.density = 2;
  options.modulus = 8;
  options.fixedFaces = ends;
  const LinearSecondOrderSystem system = assembleFiniteDifferenceWave(line, buildNeighbourList(CellList<1>(line, 1.5 * dx)), options);
  const std::vector<Real> omega2 = squaredFrequencies(line, system, ends);
  ASSERT_EQ(omega2.size(), 19u);
  for (int n = 1; n <= 19; ++n) {
    const Real expected = finiteDifferenceFrequency(n * M_PI / length, dx, c);
    EXPECT_NEAR(std::sqrt(omega2[static_cast<std::size_t>(n - 1)]), expected, 1e-10 * expected) << "mode " << n;
  }
  // The stiffness is symmetric and annihilates nothing but what the fixed ends remove.
  EXPECT_NEAR((Eigen::MatrixXd(system.stiffness()) - Eigen::MatrixXd(system.stiffness()).transpose()).norm(), 0, 1e-12);
}

TEST(FiniteDifferenceWaveOperator, TwoDimensionalLowestModeOfASquare) {
  // Square [0,1]^2, all faces fixed: omega_11^2 = (2c/dx)^2 * 2 sin^2(pi dx / 2).
  const Real dx = 0.125;
  const ParticleSet<2> square = makeRectangle(Vec2(0, 0), Vec2(1, 1), dx);
  const std::uint8_t all = 0x0F;
  FiniteDifferenceWaveOptions options;
  options.spacing = dx;
  options.fixedFaces = all;
  const LinearSecondOrderSystem system =
      assembleFiniteDifferenceWave(square, buildNeighbourList(CellList<2>(square, 1.2 * dx)), options);
  const std::vector<Real> omega2 = squaredFrequencies(square, system, all);
  ASSERT_EQ(omega2.size(), 49u);
  const Real s = std::sin(M_PI * dx / 2);
  EXPECT_NEAR(omega2.front(), std::pow(2 / dx, 2) * 2 * s * s, 1e-9);
}

TEST(FiniteDifferenceWaveOperator, AFreeFaceIsRejectedNamingTheParticle) {
  const ParticleSet<1> line = makeLine(0, 1, 0.25);
  FiniteDifferenceWaveOptions options;
  options.spacing = 0.25;
  options.fixedFaces = faceBit(BoxFace::MinusX);  // +x end left free
  try {
    assembleFiniteDifferenceWave(line, buildNeighbourList(CellList<1>(line, 0.3)), options);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "boundary");
    EXPECT_NE(std::string(e.what()).find("particle 4"), std::string::npos) << e.what();
  }
  options.spacing = -1;
  EXPECT_THROW(assembleFiniteDifferenceWave(line, buildNeighbourList(CellList<1>(line, 0.3)), options), InputError);
}
