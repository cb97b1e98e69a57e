#include "kernels/CubicSplineKernel.hpp"

#include "kernels/KernelProfiles.hpp"

#include <array>
#include <cmath>

namespace mfwave {

namespace {
// Li primer eq. (8): 2/3 (1-D), 10/(7 pi) (2-D), 1/pi (3-D).
constexpr std::array<Real, 3> kCubicSplineSigma = {2.0 / 3.0, 10.0 / (7.0 * kPi), 1.0 / kPi};
}  // namespace

CubicSplineKernel::CubicSplineKernel(int dimension, Real h)
    : Kernel(dimension, h, 2.0, kCubicSplineSigma, "smoothing_length") {}

// f = 1 - 3/2 q^2 + 3/4 q^3 (q <= 1), 1/4 (2 - q)^3 (1 < q <= 2).
Real CubicSplineKernel::shape(Real q) const { return CubicSplineProfile{}.shape(q); }

Real CubicSplineKernel::slopeOverQ(Real q) const { return CubicSplineProfile{}.slopeOverQ(q); }

Kernel::Curvature CubicSplineKernel::curvature(Real q) const {
  if (q < 1.0) return {-3.0 + 2.25 * q, -3.0 + 4.5 * q};
  if (q < 2.0) {
    const Real t = 2.0 - q;
    return {-0.75 * t * t / q, 1.5 * t};
  }
  return {0.0, 0.0};
}

}  // namespace mfwave
