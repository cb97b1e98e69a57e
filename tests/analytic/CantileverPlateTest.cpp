// The thin-plate reference of the oscillating cantilever plate (Gray-Monaghan-Swift): the mode
// root, the frequency of the GMS plate, the boundary conditions of the mode shape, the initial
// velocity, and the Timoshenko estimates (first order against the exact beam root).

#include "analytic/CantileverPlate.hpp"
#include "core/Error.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace mfwave;

namespace {

constexpr double pi = mfwave::kPi;

// The GMS plate: L = 0.2, H = 0.02, E = 2e6, nu = 0.3975, rho = 1000.
CantileverPlate gmsPlate(double thickness = 0.02) {
  return CantileverPlate(0.2, thickness, Material::fromYoung(2e6, 0.3975, 1000));
}

}  // namespace

TEST(CantileverPlate, FirstModeRootSolvesTheFrequencyEquation) {
  const double x = CantileverPlate::firstModeRoot();
  EXPECT_NEAR(x, 1.8751040687, 1e-10);
  EXPECT_NEAR(std::cos(x) * std::cosh(x), -1, 1e-14);
}

TEST(CantileverPlate, ThinPlateFrequencyOfTheGmsPlate) {
  const CantileverPlate plate = gmsPlate();
  // By hand: omega^2 = E H^2 k^4 / (12 rho (1 - nu^2)) with k = 1.8751040687 / 0.2.
  const double k = 1.8751040687119611 / 0.2;
  const double omega2 = 2e6 * 0.02 * 0.02 * std::pow(k, 4) / (12 * 1000 * (1 - 0.3975 * 0.3975));
  EXPECT_NEAR(plate.wavenumber(), k, 1e-12 * k);
  EXPECT_NEAR(plate.angularFrequency() * plate.angularFrequency(), omega2, 1e-6 * omega2);
  EXPECT_NEAR(plate.period(), 2 * pi / std::sqrt(omega2), 1e-6 * plate.period());
  EXPECT_NEAR(omega2, 611.76, 0.01);
  EXPECT_NEAR(plate.period(), 0.25403, 1e-5);
  // c0 = sqrt(K / rho), K = E / (3 (1 - 2 nu)).
  EXPECT_NEAR(plate.referenceSoundSpeed(), std::sqrt(2e6 / (3 * (1 - 2 * 0.3975)) / 1000), 1e-12);
}

TEST(CantileverPlate, ModeShapeIsClampedAtTheRootAndFreeAtTheTip) {
  const CantileverPlate plate = gmsPlate();
  const double L = plate.length(), k = plate.wavenumber();
  EXPECT_NEAR(plate.modeShape(0), 0, 1e-15);
  EXPECT_NEAR(plate.modeShapeDerivative(0, 1), 0, 1e-14 * k);
  EXPECT_NEAR(plate.modeShapeDerivative(L, 2), 0, 1e-12 * k * k);
  EXPECT_NEAR(plate.modeShapeDerivative(L, 3), 0, 1e-12 * k * k * k);
  EXPECT_LT(plate.modeShape(L), 0);  // the sign convention of the header: f(L) = Q / M < 0
  // The derivatives are those of f (central differences, step 1e-5 L) and f'''' = k^4 f.
  const double x = 0.37 * L, e = 1e-5 * L;
  for (int n = 0; n < 3; ++n) {
    const double fd = (plate.modeShapeDerivative(x + e, n) - plate.modeShapeDerivative(x - e, n)) / (2 * e);
    EXPECT_NEAR(plate.modeShapeDerivative(x, n + 1), fd, 1e-7 * std::pow(k, n + 1)) << "order " << n + 1;
  }
  const double f4 = (plate.modeShapeDerivative(x + e, 3) - plate.modeShapeDerivative(x - e, 3)) / (2 * e);
  EXPECT_NEAR(f4, std::pow(k, 4) * plate.modeShape(x), 1e-6 * std::pow(k, 4));
  EXPECT_THROW(plate.modeShapeDerivative(x, 4), InputError);
}

TEST(CantileverPlate, InitialVelocityStartsTheTipAtVfTimesC0) {
  const CantileverPlate plate = gmsPlate();
  const double vf = 0.05, c0 = plate.referenceSoundSpeed(), L = plate.length();
  EXPECT_NEAR(plate.initialVelocity(L, vf), vf * c0, 1e-12);
  EXPECT_EQ(plate.initialVelocity(0, vf), 0);
  EXPECT_EQ(plate.initialVelocity(-0.01, vf), 0);  // the clamp
  EXPECT_GT(plate.initialVelocity(0.5 * L, vf), 0);
  EXPECT_LT(plate.initialVelocity(0.5 * L, vf), vf * c0);
  // w(x, t) = (V_f c0 / omega) f / f(L) sin(omega t): w_t(x, 0) is the initial velocity.
  const double x = 0.6 * L, dt = 1e-7;
  EXPECT_NEAR((plate.displacement(x, dt, vf) - plate.displacement(x, -dt, vf)) / (2 * dt),
              plate.initialVelocity(x, vf), 1e-7 * vf * c0);
  EXPECT_NEAR(plate.tipAmplitude(vf), vf * c0 / plate.angularFrequency(), 1e-15);
  EXPECT_NEAR(plate.displacement(L, plate.period() / 4, vf), plate.tipAmplitude(vf), 1e-12);
}

TEST(CantileverPlate, TimoshenkoFirstOrderMatchesTheExactBeamRoot) {
  const double kappa = 5.0 / 6.0;
  // Constants of the clamped-free mode (1 for a sine).
  const CantileverPlate gms = gmsPlate();
  EXPECT_GT(gms.rotaryInertiaRatio(), 0);
  EXPECT_GT(gms.shearRatio(), 0);
  // Shear and rotary inertia lower the frequency; the first-order estimate misses the exact
  // Timoshenko root by O((H/L)^4), so the miss falls ~16x when H halves, while the correction
  // itself falls ~4x.
  double previousCorrection = 0, previousMiss = 0;
  for (const double H : {0.02, 0.01, 0.005}) {
    const CantileverPlate plate = gmsPlate(H);
    const double thin = plate.angularFrequency();
    const double exact = plate.timoshenkoAngularFrequency(kappa);
    const double first = plate.timoshenkoFirstOrderAngularFrequency(kappa);
    EXPECT_LT(exact, thin);
    EXPECT_LT(first, thin);
    const double correction = (thin - exact) / thin, miss = std::abs(first - exact) / thin;
    EXPECT_LT(miss, 0.05 * correction) << "H = " << H;
    if (previousCorrection > 0) {
      EXPECT_NEAR(previousCorrection / correction, 4, 0.2) << "H = " << H;
      EXPECT_GT(previousMiss / miss, 10) << "H = " << H;
    }
    previousCorrection = correction;
    previousMiss = miss;
  }
  EXPECT_NEAR(gms.timoshenkoPeriod(kappa), 2 * pi / gms.timoshenkoAngularFrequency(kappa), 1e-15);
  EXPECT_NEAR(gms.timoshenkoFirstOrderPeriod(kappa), 2 * pi / gms.timoshenkoFirstOrderAngularFrequency(kappa),
              1e-15);
  EXPECT_GT(gms.timoshenkoPeriod(kappa), gms.period());
}

TEST(CantileverPlate, RejectsBadParameters) {
  const Material m = Material::fromYoung(2e6, 0.3975, 1000);
  EXPECT_THROW(CantileverPlate(0, 0.02, m), InputError);
  EXPECT_THROW(CantileverPlate(0.2, -0.02, m), InputError);
  EXPECT_THROW(gmsPlate().timoshenkoAngularFrequency(0), InputError);
  EXPECT_THROW(gmsPlate().timoshenkoFirstOrderAngularFrequency(-1), InputError);
}
