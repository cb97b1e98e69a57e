// Lattice dispersion of an interior stencil (numerics/LatticeDispersion): the second-order
// finite-difference Laplacian against its closed form, and the very weak form SPH's interior
// stencil (published, row-sum corrected, consistent when the method has it) as measured.

#include "numerics/LatticeDispersion.hpp"
#include "spectra/VeryWeakSphDispersion.hpp"
#include "core/Error.hpp"
#include "methods/finite_difference/FiniteDifferenceWaveOperator.hpp"
#include "neighbours/CellList.hpp"
#include "neighbours/NeighbourList.hpp"
#include "particles/BoxFace.hpp"
#include "particles/Lattice.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <vector>

using namespace mfwave;

namespace {


// The scalar finite-difference wave rho u_tt = E Lap u on the lattice [-4 dx, 4 dx]^D, rho = 2,
// E = 8 (c = 2), dx = 0.25, and the particle at the origin.
template <int D>
struct FiniteDifferenceLattice {
  static constexpr Real dx = 0.25, c = 2;
  ParticleSet<D> particles = makeLattice<D>(Vec<D>::Constant(-4 * dx), Vec<D>::Constant(4 * dx), dx);
  LinearSecondOrderSystem system = assemble();
  Index centre = find(Vec<D>::Zero());

  LinearSecondOrderSystem assemble() const {
    FiniteDifferenceWaveOptions options;
    options.spacing = dx;
    options.density = 2;
    options.modulus = 8;
    options.fixedFaces = allFaces(D);  // the boundary rows are left empty; the centre row is interior
    return assembleFiniteDifferenceWave(particles, buildNeighbourList(CellList<D>(particles, 1.2 * dx)), options);
  }
  Index find(const Vec<D>& x) const {
    for (Index i = 0; i < particles.physicalCount(); ++i)
      if ((particles.position(i) - x).norm() < 1e-12) return i;
    return -1;
  }
};

// omega of the finite-difference Laplacian along a unit direction n: (2 c / dx) sqrt(sum_j sin^2(k n_j dx / 2)),
// and its derivative in k.
template <int D>
Real fdOmega(Real k, const Vec<D>& n, Real dx, Real c) {
  Real sum = 0;
  for (int j = 0; j < D; ++j) sum += std::pow(std::sin(k * n(j) * dx / 2), 2);
  return 2 * c / dx * std::sqrt(sum);
}
template <int D>
Real fdGroup(Real k, const Vec<D>& n, Real dx, Real c) {
  Real sum = 0;
  for (int j = 0; j < D; ++j) sum += n(j) * std::sin(k * n(j) * dx);
  return 2 * c * c / dx * sum / (2 * fdOmega<D>(k, n, dx, c));
}

template <int D>
void expectScalarClosedForm() {
  const FiniteDifferenceLattice<D> lattice;
  ASSERT_GE(lattice.centre, 0);
  const auto stencil = extractLatticeStencil(lattice.system, lattice.particles, lattice.centre);
  EXPECT_EQ(stencil.components, 1);
  EXPECT_EQ(stencil.size(), 2 * D + 1);
  const Real dx = lattice.dx, c = lattice.c;
  for (const Vec<D>& n : {latticeAxis<D>(), latticeDiagonal<D>()})
    for (Real kdx = 0.01; kdx <= kPi + 1e-12; kdx += (kPi - 0.01) / 40) {
      const Real k = kdx / dx;
      const LatticeMode mode = latticeMode(stencil, n, k, Polarisation::Scalar);
      const Real omega = fdOmega<D>(k, n, dx, c);
      EXPECT_NEAR(mode.omega, omega, 1e-12 * omega) << D << "-D, kdx " << kdx;
      EXPECT_NEAR(mode.phaseSpeed, omega / k, 1e-12 * c);
      EXPECT_NEAR(mode.groupSpeed, fdGroup<D>(k, n, dx, c), 1e-12 * c) << D << "-D, kdx " << kdx;
    }
  const LongWaveLimit limit = longWaveLimit(stencil, latticeDiagonal<D>(), Polarisation::Scalar);
  EXPECT_EQ(limit.gap, 0);
  EXPECT_NEAR(limit.speed, c, 1e-13 * c);
}

}  // namespace

TEST(LatticeDispersion, ScalarFiniteDifferenceMatchesTheClosedFormIn1D2D3D) {
  expectScalarClosedForm<1>();
  expectScalarClosedForm<2>();
  expectScalarClosedForm<3>();
}

TEST(LatticeDispersion, OneDimensionalFiniteDifferenceIsAPWaveWithClosedFormPointsPerWavelength) {
  const FiniteDifferenceLattice<1> lattice;
  const auto stencil = extractLatticeStencil(lattice.system, lattice.particles, lattice.centre);
  const Real dx = lattice.dx, c = lattice.c;
  const LatticeMode p = latticeMode(stencil, Vec1(1), 1.3 / dx, Polarisation::P);
  EXPECT_NEAR(p.omega, 2 * c / dx * std::sin(0.65), 1e-12 * p.omega);
  EXPECT_EQ(p.alignment, 1);
  EXPECT_THROW(latticeMode(stencil, Vec1(1), 1.0, Polarisation::S), InputError);
  // Phase speed sin(kdx/2) / (kdx/2) = 0.99 at kdx = 0.49037... (the root), ppw = 2 pi / kdx.
  const AccuracyResolution r = pointsPerWavelength(stencil, Vec1(1), Polarisation::P, c, dx, 0.01);
  ASSERT_TRUE(r.attained);
  EXPECT_FALSE(r.wholeBand);
  EXPECT_NEAR(std::sin(r.kdx / 2) / (r.kdx / 2), 0.99, 1e-10);
  EXPECT_NEAR(r.pointsPerWavelength, 2 * kPi / r.kdx, 1e-12);
  EXPECT_NEAR(r.pointsPerWavelength, 12.81, 0.01);
}

TEST(LatticeDispersion, VectorFiniteDifferenceLaplacianHasPAndSOnTheClosedForm) {
  // The D x D analogue u_tt = c^2 Lap u (each component on its own): P and S both on the scalar
  // closed form, along the axis and the diagonal.
  const FiniteDifferenceLattice<3> scalar;
  const auto vector = [](const SparseMatrix& m) {
    std::vector<Triplet> entries;
    for (int col = 0; col < m.outerSize(); ++col)
      for (SparseMatrix::InnerIterator it(m, col); it; ++it)
        for (int i = 0; i < 3; ++i) entries.emplace_back(3 * it.row() + i, 3 * it.col() + i, it.value());
    SparseMatrix out(3 * m.rows(), 3 * m.cols());
    out.setFromTriplets(entries.begin(), entries.end());
    return out;
  };
  const LinearSecondOrderSystem system(vector(scalar.system.mass()), SparseMatrix(), vector(scalar.system.stiffness()));
  const auto stencil = extractLatticeStencil(system, scalar.particles, scalar.centre);
  EXPECT_EQ(stencil.components, 3);
  const Real dx = scalar.dx, c = scalar.c;
  for (const Vec3& n : {latticeAxis<3>(), latticeDiagonal<3>()})
    for (Real kdx : {0.01, 0.7, 2.0, kPi}) {
      const Real omega = fdOmega<3>(kdx / dx, n, dx, c);
      for (auto polarisation : {Polarisation::P, Polarisation::S})
        EXPECT_NEAR(latticeMode(stencil, n, kdx / dx, polarisation).omega, omega, 1e-12 * omega);
    }
  EXPECT_THROW(latticeMode(stencil, latticeAxis<3>(), 1.0, Polarisation::Scalar), InputError);
  // The scalar system has no P or S in 3-D.
  const auto scalarStencil = extractLatticeStencil(scalar.system, scalar.particles, scalar.centre);
  EXPECT_THROW(latticeMode(scalarStencil, latticeAxis<3>(), 1.0, Polarisation::P), InputError);
}

TEST(LatticeDispersion, RejectsAStencilWhoseSymbolIsNotReal) {
  LatticeStencil<1> oneSided;
  oneSided.components = 1;
  oneSided.offsets = {Vec1(0), Vec1(1)};
  oneSided.blocks = {Eigen::MatrixXd::Constant(1, 1, -1), Eigen::MatrixXd::Constant(1, 1, 1)};
  EXPECT_THROW(latticeModes(oneSided, Vec1(1), 0.5), InputError);
  EXPECT_NEAR(stencilSymbol(oneSided, Vec1(0.5)).imaginaryRatio, std::sin(0.5) / 2, 1e-15);
  EXPECT_THROW(latticeModes(oneSided, Vec1(0), 0.5), InputError);
  EXPECT_THROW(latticeModes(oneSided, Vec1(1), 0), InputError);
}

namespace {

const Material kUnitMaterial = Material::fromLame(1, 1, 1);  // c_p = sqrt(3), c_s = 1

Real waveSpeed(Polarisation polarisation) {
  return polarisation == Polarisation::P ? kUnitMaterial.pWaveSpeed() : kUnitMaterial.sWaveSpeed();
}

}  // namespace

TEST(VeryWeakSphDispersion, PublishedInteriorRowHasAGapAndFastLongWaves) {
  // Cubic spline, h = dx = 1, lambda = mu = rho = 1: the row sum -0.0559 / h^2 of the published
  // interior row (OperatorTest) is an isotropic elastic foundation, omega(k -> 0) = 0.2365 / h for
  // P and S alike, and the long waves on top of it run 3.3 to 5.7 % too fast.
  const auto lattice = veryWeakSphInteriorStencil<3>(VeryWeakSphDispersionVariant::Published, "cubic_spline", 1.0,
                                                     kUnitMaterial, 1.0);
  EXPECT_EQ(lattice.stencil.size(), 27);
  EXPECT_LT(lattice.translationDifference, 1e-13);
  const Eigen::MatrixXd rowSum = lattice.stencil.rowSum();
  EXPECT_NEAR(rowSum(0, 0), -0.0559226, 1e-7);
  EXPECT_LT((rowSum - rowSum(0, 0) * Eigen::MatrixXd::Identity(3, 3)).cwiseAbs().maxCoeff(), 1e-14);
  struct Expected {
    Vec3 n;
    Polarisation polarisation;
    Real speedRatio;
  };
  for (const Expected& e : {Expected{latticeAxis<3>(), Polarisation::P, 1.0357617},
                            Expected{latticeAxis<3>(), Polarisation::S, 1.0539055},
                            Expected{latticeDiagonal<3>(), Polarisation::P, 1.0333933},
                            Expected{latticeDiagonal<3>(), Polarisation::S, 1.0573872}}) {
    const Real c = waveSpeed(e.polarisation);
    const LongWaveLimit limit = longWaveLimit(lattice.stencil, e.n, e.polarisation);
    EXPECT_NEAR(limit.gap, std::sqrt(-rowSum(0, 0)), 1e-12);
    EXPECT_NEAR(limit.gap, 0.2364797, 1e-7);
    EXPECT_NEAR(limit.speed / c, e.speedRatio, 1e-7) << polarisationName(e.polarisation);
    EXPECT_NEAR(limit.alignment, e.polarisation == Polarisation::P ? 1 : 0, 1e-12);
    // omega^2 = gap^2 + c_long^2 k^2 for long waves: the phase speed diverges like gap / k.
    const Real k = 1e-3;
    const LatticeMode mode = latticeMode(lattice.stencil, e.n, k, e.polarisation);
    EXPECT_NEAR(mode.omega, std::hypot(limit.gap, limit.speed * k), 1e-9);
    EXPECT_GT(mode.phaseSpeed / c, 100);
    EXPECT_FALSE(pointsPerWavelength(lattice.stencil, e.n, e.polarisation, c, 1.0).attained);
  }
  // Along the axis at k dx = pi / 4 (8 points per wavelength).
  EXPECT_NEAR(latticeMode(lattice.stencil, latticeAxis<3>(), kPi / 4, Polarisation::P).phaseSpeed / waveSpeed(Polarisation::P),
              1.0242054, 1e-6);
  EXPECT_NEAR(latticeMode(lattice.stencil, latticeAxis<3>(), kPi / 4, Polarisation::S).phaseSpeed, 1.0702527, 1e-6);
}

TEST(VeryWeakSphDispersion, RowSumCorrectionRemovesTheGapButNotTheSpeedError) {
  const auto lattice = veryWeakSphInteriorStencil<3>(VeryWeakSphDispersionVariant::PublishedRowSumCorrected,
                                                     "cubic_spline", 1.0, kUnitMaterial, 1.0);
  EXPECT_LT(lattice.stencil.rowSum().cwiseAbs().maxCoeff(), 1e-14);
  for (const Vec3& n : {latticeAxis<3>(), latticeDiagonal<3>()})
    for (auto polarisation : {Polarisation::P, Polarisation::S}) {
      const Real c = waveSpeed(polarisation);
      const LongWaveLimit limit = longWaveLimit(lattice.stencil, n, polarisation);
      EXPECT_EQ(limit.gap, 0);
      const LatticeMode mode = latticeMode(lattice.stencil, n, 1e-4, polarisation);
      EXPECT_NEAR(mode.phaseSpeed, limit.speed, 1e-7 * c);
      EXPECT_NEAR(mode.groupSpeed, limit.speed, 1e-7 * c);
      EXPECT_GT(limit.speed / c, 1.03);
      EXPECT_FALSE(pointsPerWavelength(lattice.stencil, n, polarisation, c, 1.0).attained);
    }
}

TEST(VeryWeakSphDispersion, ConsistentVariantHasExactLongWaves) {
  const auto lattice = veryWeakSphInteriorStencil<3>(VeryWeakSphDispersionVariant::Consistent, "cubic_spline", 1.0,
                                                     kUnitMaterial, 1.0);
  EXPECT_LT(lattice.translationDifference, 1e-12);
  EXPECT_LT(lattice.stencil.rowSum().cwiseAbs().maxCoeff(), 1e-13);
  for (const Vec3& n : {latticeAxis<3>(), latticeDiagonal<3>()})
    for (auto polarisation : {Polarisation::P, Polarisation::S}) {
      const Real c = waveSpeed(polarisation);
      const LongWaveLimit limit = longWaveLimit(lattice.stencil, n, polarisation);
      EXPECT_EQ(limit.gap, 0);
      EXPECT_NEAR(limit.speed / c, 1, 1e-6) << polarisationName(polarisation);
      EXPECT_NEAR(latticeMode(lattice.stencil, n, 1e-3, polarisation).phaseSpeed / c, 1, 1e-6);
      // The error is O((k dx)^2): a quarter of it at half the wavenumber.
      const Real e1 = 1 - latticeMode(lattice.stencil, n, 0.2, polarisation).phaseSpeed / c;
      const Real e2 = 1 - latticeMode(lattice.stencil, n, 0.1, polarisation).phaseSpeed / c;
      EXPECT_NEAR(e1 / e2, 4, 0.01);
      EXPECT_TRUE(pointsPerWavelength(lattice.stencil, n, polarisation, c, 1.0).attained);
    }
  // Along the axis the interior row acts like the 3-point Laplacian for P and S:
  // omega = (2 c / dx) sin(k dx / 2), 0.97450 of c at k dx = pi / 4.
  for (auto polarisation : {Polarisation::P, Polarisation::S})
    for (Real kdx : {0.3, kPi / 4, 2.0, kPi}) {
      const Real c = waveSpeed(polarisation);
      EXPECT_NEAR(latticeMode(lattice.stencil, latticeAxis<3>(), kdx, polarisation).omega, 2 * c * std::sin(kdx / 2),
                  1e-10 * c);
    }
}

// Issue 15, "why": the interior row of the very weak SPH is a sampled kernel Hessian, whose symbol
// is by Poisson summation sum_m (k + g_m)(k + g_m)^T W^(k + g_m) plus the like shear terms: positive
// semi-definite whenever the kernel's Fourier transform W^ is non-negative. Wendland kernels are
// positive definite functions in 1-3 D, so their consistent interior rows are stable at every
// h / dx; the radial cubic spline's 3-D transform changes sign, and at h / dx = 1.5 a grid-scale
// mode has omega^2 < 0 (docs/theory/very-weak-sph.md, table from vwsph_interior_spectrum).
TEST(SymbolExtremes, ConsistentInteriorRowsArePositiveWithWendlandAndNotWithTheCubicSpline) {
  const Material material = Material::fromLame(1, 1, 1);
  for (const Real ratio : {1.0, 1.5, 2.0}) {
    const auto wendland = veryWeakSphInteriorStencil<2>(VeryWeakSphDispersionVariant::Consistent, "wendland_c2", ratio,
                                                        material);
    const SymbolExtremes<2> e = symbolExtremes(wendland.stencil, wendland.spacing, 24);
    EXPECT_GE(e.smallest, -1e-12 * e.largest) << "h/dx = " << ratio;
    EXPECT_LT(e.largestImaginaryRatio, 1e-12);
  }
  const auto cubic2 = veryWeakSphInteriorStencil<2>(VeryWeakSphDispersionVariant::Consistent, "cubic_spline", 2.0,
                                                    material);
  const SymbolExtremes<2> c2 = symbolExtremes(cubic2.stencil, cubic2.spacing, 24);
  EXPECT_NEAR(c2.smallest / c2.largest, -0.01273, 2e-4);
  const auto cubic3 = veryWeakSphInteriorStencil<3>(VeryWeakSphDispersionVariant::Consistent, "cubic_spline", 1.5,
                                                    material);
  const SymbolExtremes<3> c3 = symbolExtremes(cubic3.stencil, cubic3.spacing, 4);
  EXPECT_NEAR(c3.smallest / c3.largest, -0.06568, 1e-3);
  EXPECT_NEAR(c3.smallestAt.minCoeff(), M_PI, 1e-12);  // the zone corner (pi, pi, pi)
  const auto wendland3 = veryWeakSphInteriorStencil<3>(VeryWeakSphDispersionVariant::Consistent, "wendland_c2", 1.5,
                                                       material);
  const SymbolExtremes<3> w3 = symbolExtremes(wendland3.stencil, wendland3.spacing, 8);
  EXPECT_GE(w3.smallest, -1e-12 * w3.largest);
  EXPECT_THROW(symbolExtremes(cubic2.stencil, cubic2.spacing, 0), InputError);
}

// The Galerkin variant as the spectra tools see it (vwsph_interior_spectrum, spectra's
// vwsph_galerkin): translation exact, omega^2 >= 0 over the whole zone in 1-3 D (round-off only),
// and along an axis the finite-difference line, omega = (2 c / dx) sin(k dx / 2) for P and S.
TEST(SymbolExtremes, GalerkinInteriorRowsAreNonNegativeEverywhereAndTheAxisIsTheFiniteDifferenceLine) {
  const Material material = Material::fromLame(1, 1, 1);
  const auto g1 = veryWeakSphInteriorStencil<1>(VeryWeakSphDispersionVariant::Galerkin, "cubic_spline", 1.0, material);
  const auto g2 = veryWeakSphInteriorStencil<2>(VeryWeakSphDispersionVariant::Galerkin, "cubic_spline", 1.0, material);
  const auto g3 = veryWeakSphInteriorStencil<3>(VeryWeakSphDispersionVariant::Galerkin, "cubic_spline", 1.0, material);
  EXPECT_LT(g3.translationDifference, 1e-12);
  const SymbolExtremes<1> e1 = symbolExtremes(g1.stencil, g1.spacing, 64);
  const SymbolExtremes<2> e2 = symbolExtremes(g2.stencil, g2.spacing, 32);
  const SymbolExtremes<3> e3 = symbolExtremes(g3.stencil, g3.spacing, 12);
  EXPECT_GE(e1.smallest, -1e-12 * e1.largest);
  EXPECT_GE(e2.smallest, -1e-12 * e2.largest);
  EXPECT_GE(e3.smallest, -1e-12 * e3.largest);
  // omega_max dx = 2 c_p with c_p = sqrt 3 (dx = 1): omega_max^2 = 12, at k dx = (pi, pi, pi)
  EXPECT_NEAR(e3.largest, 12.0, 1e-9);
  for (auto polarisation : {Polarisation::P, Polarisation::S})
    for (Real kdx : {0.3, kPi / 4, 2.0}) {
      const Real c = waveSpeed(polarisation);
      EXPECT_NEAR(latticeMode(g3.stencil, latticeAxis<3>(), kdx, polarisation).omega, 2 * c * std::sin(kdx / 2),
                  1e-10 * c);
    }
}
