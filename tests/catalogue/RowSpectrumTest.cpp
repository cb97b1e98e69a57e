// The plan's spectral figures from a method's interior row, against closed forms.
#include "catalogue/RowSpectrum.hpp"

#include "spectra/LatticeMethods.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace mfwave {
namespace {

TEST(RowSpectrum, TheFiniteDifferenceLimitIsTwoCOverDxTimesRootD) {
  // omega^2 = (4 c^2 / dx^2) sum_a sin^2(k_a dx / 2): largest at the zone corner, 2 c sqrt(D) / dx.
  LatticeMethodSettings s;
  s.material = Material::fromLame(1, 1, 1);  // c_p = sqrt 3
  const Real c = std::sqrt(3.0), dx = 0.1;
  EXPECT_NEAR(rowSpectrum<1>(latticeMethodStencil<1>("finite_difference", s, dx), dx).omegaMax, 2 * c / dx, 1e-9);
  EXPECT_NEAR(rowSpectrum<2>(latticeMethodStencil<2>("finite_difference", s, dx), dx).omegaMax,
              2 * c * std::sqrt(2.0) / dx, 1e-9);
  EXPECT_NEAR(rowSpectrum<3>(latticeMethodStencil<3>("finite_difference", s, dx), dx).omegaMax,
              2 * c * std::sqrt(3.0) / dx, 1e-9);
}

TEST(RowSpectrum, FiniteDifferencesAtCourantOneInOneDimensionHaveNoPhaseError) {
  // The 1-D wave equation's "magic time step": the three-point Laplacian stepped by central
  // differences at c dt = dx is exact, its space and time errors cancel.
  LatticeMethodSettings s;
  const Real c = s.material.pWaveSpeed(), dx = 0.05;
  const auto row = latticeMethodStencil<1>("finite_difference", s, dx);
  const Real nu = c / (8 * dx);  // eight points per wavelength
  const RowPhaseError atOne = rowPhaseError<1>(row, s.material, dx, nu, dx / c, IntegratorKind::CentralDifference);
  EXPECT_LT(atOne.total, 1e-12);
  // The row alone lags: omega_h / (c k) = sin(k dx / 2) / (k dx / 2), k dx = pi / 4.
  const Real x = kPi / 8;
  EXPECT_NEAR(atOne.spatial, 1 - std::sin(x) / x, 1e-12);
  EXPECT_NEAR(atOne.pointsPerWavelength, 8, 1e-12);
  // Half the step leaves part of the lag: between the two.
  const RowPhaseError atHalf = rowPhaseError<1>(row, s.material, dx, nu, dx / c / 2, IntegratorKind::CentralDifference);
  EXPECT_GT(atHalf.total, 1e-4);
  EXPECT_LT(atHalf.total, atOne.spatial);
}

TEST(RowSpectrum, TheIntegratorsMapFrequenciesAsTheirRecurrencesDo) {
  EXPECT_NEAR(discreteFrequency(1.0, 1.0, IntegratorKind::CentralDifference), 2 * std::asin(0.5), 1e-15);
  EXPECT_NEAR(discreteFrequency(1.0, 1.0, IntegratorKind::Newmark), 2 * std::atan(0.5), 1e-15);
  EXPECT_TRUE(std::isnan(discreteFrequency(3.0, 1.0, IntegratorKind::CentralDifference)));  // beyond the limit
  EXPECT_NEAR(planeWaveError(0.01, 2), 2 * std::sin(kPi * 0.02), 1e-15);
}

TEST(RowSpectrum, RkCollocationsThreeDimensionalInteriorGrowsFromASupportOfTwoAndAHalf) {
  // The stability atlas (docs/studies/stability-atlas.md): m = 2, a / h = 2.2 is the widest stable
  // 3-D support; at 2.5 the mass symbol changes sign and the interior rows grow.
  LatticeMethodSettings s;
  s.rkOrder = 2;
  s.rkSupportRatio = 2.2;
  EXPECT_FALSE(rowSpectrum<3>(latticeMethodStencil<3>("rkcm", s, 1.0), 1.0).growing);
  s.rkSupportRatio = 2.5;
  EXPECT_TRUE(rowSpectrum<3>(latticeMethodStencil<3>("rkcm", s, 1.0), 1.0).growing);
}

TEST(RowSpectrum, TheGalerkinVeryWeakRowIsStableAndSecondOrder) {
  LatticeMethodSettings s;
  const Real dx = 1.0;
  const auto row = latticeMethodStencil<3>("vwsph_galerkin", s, dx);
  EXPECT_FALSE(rowSpectrum<3>(row, dx).growing);
  const Real c = s.material.sWaveSpeed();
  const Real coarse = rowPhaseError<3>(row, s.material, dx, c / (10 * dx), 1e-6, IntegratorKind::CentralDifference).spatial;
  const Real fine = rowPhaseError<3>(row, s.material, dx, c / (20 * dx), 1e-6, IntegratorKind::CentralDifference).spatial;
  EXPECT_NEAR(std::log2(coarse / fine), 2.0, 0.1);
}

}  // namespace
}  // namespace mfwave
