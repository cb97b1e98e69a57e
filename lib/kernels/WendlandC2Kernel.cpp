#include "kernels/WendlandC2Kernel.hpp"

#include "kernels/KernelProfiles.hpp"

#include <array>
#include <cmath>

namespace mfwave {

namespace {
// Derived analytically (1 / (S_d int_0^2 q^{d-1} f dq)) and checked by quadrature in the tests:
// 5/8 for the 1-D function, 7/(4 pi) and 21/(16 pi) for the 2-D/3-D one.
constexpr std::array<Real, 3> kWendlandC2Sigma = {5.0 / 8.0, 7.0 / (4.0 * kPi), 21.0 / (16.0 * kPi)};
}  // namespace

WendlandC2Kernel::WendlandC2Kernel(int dimension, Real h)
    : Kernel(dimension, h, 2.0, kWendlandC2Sigma, "smoothing_length"), oneD_(dimension == 1) {}

// With s = 1 - q/2:
//   1-D:    f = s^3 (3/2 q + 1),  f'/q = -3 s^2,  f'' = 3/2 s (3 q - 2)
//   2-/3-D: f = s^4 (2 q + 1),    f'/q = -5 s^3,  f'' = 5 s^2 (2 q - 1)
Real WendlandC2Kernel::shape(Real q) const { return WendlandC2Profile{oneD_}.shape(q); }

Real WendlandC2Kernel::slopeOverQ(Real q) const { return WendlandC2Profile{oneD_}.slopeOverQ(q); }

Kernel::Curvature WendlandC2Kernel::curvature(Real q) const {
  if (q >= 2.0) return {0.0, 0.0};
  const Real s = 1.0 - 0.5 * q;
  if (oneD_) return {-3.0 * s * s, 1.5 * s * (3.0 * q - 2.0)};
  return {-5.0 * s * s * s, 5.0 * s * s * (2.0 * q - 1.0)};
}

}  // namespace mfwave
