// int_plane W dS through the kernel centre (Ding-Long-Wu eqs. (20), (38), (40)).

#include "kernels/KernelFactory.hpp"
#include "kernels/PlaneIntegral.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace mfwave {
namespace {

TEST(PlaneIntegral, CubicSpline3DIsSevenOverTenH) {
  for (const Real h : {0.5, 1.0, 1.7}) {
    const Real exact = 7.0 / (10.0 * h);  // so S_a = 10h/7, eq. (40)
    EXPECT_NEAR(planeIntegralThroughCentre(*makeKernel("cubic_spline", 3, h)), exact, 1e-12 * exact) << "h = " << h;
  }
}

TEST(PlaneIntegral, OtherKernelsIn3D) {
  const Real h = 0.8;
  // B-spline with support a = 2h is the same normalised kernel as the cubic spline.
  EXPECT_NEAR(planeIntegralThroughCentre(*makeKernel("cubic_b_spline", 3, 2.0 * h)), 7.0 / (10.0 * h), 1e-12);
  // Wendland C4: 2 pi sigma / h int_0^2 q f dq = 55 / (64 h), worked out by hand.
  EXPECT_NEAR(planeIntegralThroughCentre(*makeKernel("wendland_c4", 3, h)), 55.0 / (64.0 * h), 1e-12);
  // Gaussian: 2 pi sigma / h int_0^3 q e^{-q^2} dq = pi sigma (1 - e^{-9}) / h.
  const auto gauss = makeKernel("gaussian", 3, h);
  EXPECT_NEAR(planeIntegralThroughCentre(*gauss), M_PI * gauss->normalisation() * (1.0 - std::exp(-9.0)) / h, 1e-12);
}

TEST(PlaneIntegral, LowerDimensions) {
  const Real h = 0.6;
  // 2-D: a line through the centre, 2 sigma / h int_0^2 f dq = 2 * 10/(7 pi) * 3/4 / h.
  EXPECT_NEAR(planeIntegralThroughCentre(*makeKernel("cubic_spline", 2, h)), 15.0 / (7.0 * M_PI * h), 1e-12);
  // 1-D: the "plane" is the centre point itself.
  EXPECT_DOUBLE_EQ(planeIntegralThroughCentre(*makeKernel("cubic_spline", 1, h)), 2.0 / (3.0 * h));
}

}  // namespace
}  // namespace mfwave
