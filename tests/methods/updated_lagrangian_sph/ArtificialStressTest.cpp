// The Monaghan-Gray artificial stress R_i (ArtificialStress.hpp): built in the principal frame of
// sigma_i, -epsilon sigma'_aa / rho^2 on the principal directions in tension and 0 on those in
// compression, rotated back. Checked on stresses given in a rotated frame.

#include "methods/updated_lagrangian_sph/ArtificialStress.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>

using namespace mfwave;

TEST(UlsphArtificialStress, ZeroForCompression) {
  Mat2 sigma;
  sigma << -2.0, 0.7, 0.7, -1.0;  // both principal values negative
  EXPECT_EQ(artificialStressTensor<2>(sigma, 1.3, 0.3).norm(), 0.0);
  EXPECT_EQ(artificialStressTensor<1>(Mat1::Constant(-1.0), 1.0, 0.3).norm(), 0.0);
  const Mat3 pressure = -5.0 * Mat3::Identity();
  EXPECT_EQ(artificialStressTensor<3>(pressure, 2.0, 0.3).norm(), 0.0);
}

TEST(UlsphArtificialStress, RepulsiveAlongTheTensilePrincipalDirection2d) {
  const Real angle = 0.6, rho = 1.3, epsilon = 0.3;
  const Mat2 q = Eigen::Rotation2Dd(angle).toRotationMatrix();
  const Vec2 tensile = q.col(0), compressive = q.col(1);
  const Mat2 sigma = q * Vec2(2.0, -3.0).asDiagonal() * q.transpose();
  const Mat2 r = artificialStressTensor<2>(sigma, rho, epsilon);
  const Real expected = -epsilon * 2.0 / (rho * rho);
  EXPECT_NEAR((r * tensile - expected * tensile).norm(), 0.0, 1e-14);  // R n1 = -eps sigma1 / rho^2 n1
  EXPECT_NEAR((r * compressive).norm(), 0.0, 1e-14);                    // nothing on the compressive axis
  EXPECT_LT(expected, 0.0);
  EXPECT_NEAR((r - r.transpose()).norm(), 0.0, 1e-15);
}

TEST(UlsphArtificialStress, BiaxialTensionIn3dAndUniaxialIn1d) {
  const Mat3 q = Eigen::AngleAxisd(0.8, Vec3(1, 2, -1).normalized()).toRotationMatrix();
  const Mat3 sigma = q * Vec3(1.0, 4.0, -2.0).asDiagonal() * q.transpose();
  const Real rho = 2.0, epsilon = 0.2;
  const Mat3 r = artificialStressTensor<3>(sigma, rho, epsilon);
  const Mat3 expected = q * Vec3(-epsilon * 1.0 / 4, -epsilon * 4.0 / 4, 0.0).asDiagonal() * q.transpose();
  EXPECT_NEAR((r - expected).norm(), 0.0, 1e-13);
  EXPECT_NEAR(artificialStressTensor<1>(Mat1::Constant(3.0), 2.0, 0.3)(0, 0), -0.3 * 3.0 / 4, 1e-15);
}

TEST(UlsphArtificialStress, WeightIsKernelRatioToThePower) {
  EXPECT_NEAR(artificialStressWeight(0.5, 1 / 0.25, 4), 16.0, 1e-13);
  EXPECT_NEAR(artificialStressWeight(0.5, 1 / 0.25, 2.5), std::pow(2.0, 2.5), 1e-13);
}
