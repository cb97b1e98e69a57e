#include "kernels/CubicBSplineKernel.hpp"

#include "kernels/KernelProfiles.hpp"

#include <array>
#include <cmath>

namespace mfwave {

namespace {
// 1 / (S_d int_0^1 z^{d-1} phi dz): 2, 60/(7 pi), 12/pi. Equivalently the cubic spline's sigma_d
// times (3/2) 2^d, from phi(z) = 2/3 f(2z).
constexpr std::array<Real, 3> kCubicBSplineSigma = {2.0, 60.0 / (7.0 * kPi), 12.0 / kPi};
}  // namespace

CubicBSplineKernel::CubicBSplineKernel(int dimension, Real supportRadius)
    : Kernel(dimension, supportRadius, 1.0, kCubicBSplineSigma, "support_radius") {}

Real CubicBSplineKernel::shape(Real z) const { return CubicBSplineProfile{}.shape(z); }

// phi' = -8 z + 12 z^2 (z <= 1/2), -4 (1 - z)^2; phi'' = -8 + 24 z, 8 (1 - z).
Real CubicBSplineKernel::slopeOverQ(Real z) const { return CubicBSplineProfile{}.slopeOverQ(z); }

Kernel::Curvature CubicBSplineKernel::curvature(Real z) const {
  if (z < 0.5) return {-8.0 + 12.0 * z, -8.0 + 24.0 * z};
  if (z < 1.0) {
    const Real t = 1.0 - z;
    return {-4.0 * t * t / z, 8.0 * t};
  }
  return {0.0, 0.0};
}

}  // namespace mfwave
