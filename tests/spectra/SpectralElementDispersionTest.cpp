// The spectral elements' Bloch dispersion against closed forms.
#include "spectra/SpectralElementDispersion.hpp"

#include "support/InputErrorKey.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace mfwave {
namespace {

TEST(SpectralElementDispersion, LinearElementsWithLumpedMassAreTheThreePointStencil) {
  // N = 1: GLL nodes are the element ends, the lumped mass dx and the stiffness 1 / dx: the
  // three-point Laplacian, omega = (2 c / dx) sin(k dx / 2).
  const Real c = 1.5, dx = 0.1;
  for (const Real kdx : {0.3, 1.0, 2.5}) {
    const Real k = kdx / dx;
    EXPECT_NEAR(spectralElementFrequency(1, dx, c, k), 2 * c / dx * std::sin(kdx / 2), 1e-10) << kdx;
  }
  EXPECT_NEAR(spectralElementLargestFrequency(1, dx, c), 2 * c / dx, 1e-10);
}

TEST(SpectralElementDispersion, TheErrorFallsFastWithTheOrder) {
  // Eight nodes per wavelength: the error falls by about two orders of magnitude from N = 1 to N = 4, and
  // halving the spacing at N = 4 divides it by more than 2^6 (superconvergent dispersion, order 2N
  // = 8 asymptotically: measured 6.8 from 4 to 8 nodes per wavelength).
  const Real c = 1, k = 2 * kPi;
  const auto error = [&](int order, Real dx) { return std::abs(spectralElementFrequency(order, dx, c, k) / (c * k) - 1); };
  EXPECT_GT(error(1, 1.0 / 8), 1e-2);
  EXPECT_LT(error(4, 1.0 / 8), 1e-3);
  EXPECT_LT(error(4, 1.0 / 8), error(1, 1.0 / 8) / 50);
  const Real rate = std::log2(error(4, 1.0 / 4) / error(4, 1.0 / 8));
  EXPECT_GT(rate, 6);
  EXPECT_EQ(testing::inputErrorKey([] { spectralElementFrequency(0, 0.1, 1, 1); }), "order");
}

}  // namespace
}  // namespace mfwave
