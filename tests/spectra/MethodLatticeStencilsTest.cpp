// The interior rows of finite differences, collocation and the linearised updated-Lagrangian SPH:
// translation invariant, and with the long-wave speeds the methods are known to have.

#include "numerics/DispersionSpectrum.hpp"
#include "spectra/MethodLatticeStencils.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace mfwave;

TEST(MethodLatticeStencils, FiniteDifferenceRowIsTheFivePointLaplacian) {
  const auto fd = finiteDifferenceInteriorStencil<2>(0.5, 2);
  EXPECT_EQ(fd.acceleration.size(), 5);
  EXPECT_LT(fd.translationDifference, 1e-15);
  EXPECT_NEAR(fd.acceleration.rowSum()(0, 0), 0, 1e-12);
}

TEST(MethodLatticeStencils, ReproducingKernelCollocationIsTranslationInvariantAndConsistentIn2D) {
  const Material material = Material::fromLame(2, 1, 1);
  const auto rk = collocationInteriorStencil<2>(CollocationBasis::ReproducingKernel, 2, 2.5, material, 0.5);
  EXPECT_LT(rk.translationDifference, 1e-9);
  // Second-order reproduction: the long waves travel at c_p and c_s.
  const DispersionSpectrum<2> spectrum(makePeriodicLatticeOperator<2>(rk.acceleration, 0.5, 128, rk.mass));
  const auto p = spectrumLine(spectrum, LatticeDirection::Axis, Polarisation::P, material.pWaveSpeed());
  const auto s = spectrumLine(spectrum, LatticeDirection::Diagonal, Polarisation::S, material.sWaveSpeed());
  EXPECT_NEAR(p.front().phaseSpeedRatio, 1, 1e-3);  // |k| dx = 2 pi / 128: the dispersion is still 5e-4
  EXPECT_NEAR(s.front().phaseSpeedRatio, 1, 1e-3);
}

TEST(MethodLatticeStencils, LinearisedUpdatedLagrangianSphCarriesTheLatticeSumOfItsGradient) {
  // Without correction the SPH gradient of a linear field is off by the lattice sum
  // s = -sum_j x_j W'(x_j) dx (1.02237 at h = 1.3 dx in 1-D, cubic spline). It enters twice, in the
  // strain rate and in the force, so omega^2 scales by s^2 and long waves travel s times too fast.
  // The kernel-gradient correction makes the long-wave speed exact.
  UpdatedLagrangianSphOptions options;
  options.material = Material::fromYoung(1, 0, 1);
  const auto plain = updatedLagrangianSphInteriorStencil<1>(options, 0.1);
  EXPECT_LT(plain.translationDifference, 1e-6);
  const DispersionSpectrum<1> spectrum(makePeriodicLatticeOperator<1>(plain.acceleration, 0.1, 256));
  const Real c = options.material.pWaveSpeed();
  const auto line = spectrumLine(spectrum, LatticeDirection::Axis, Polarisation::P, c);
  EXPECT_NEAR(line.front().phaseSpeedRatio, 1.02237, 3e-4);  // at |k| dx = 2 pi / 256
  options.kernelGradientCorrection = true;
  const auto corrected = updatedLagrangianSphInteriorStencil<1>(options, 0.1);
  const DispersionSpectrum<1> correctedSpectrum(makePeriodicLatticeOperator<1>(corrected.acceleration, 0.1, 256));
  const auto correctedLine = spectrumLine(correctedSpectrum, LatticeDirection::Axis, Polarisation::P, c);
  EXPECT_NEAR(correctedLine.front().phaseSpeedRatio, 1, 3e-4);
}
