#include "kernels/WendlandC4Kernel.hpp"

#include "kernels/KernelProfiles.hpp"

#include <array>
#include <cmath>

namespace mfwave {

namespace {
// Derived analytically and checked by quadrature in the tests: 3/4 for the 1-D function,
// 9/(4 pi) and 495/(256 pi) for the 2-D/3-D one.
constexpr std::array<Real, 3> kWendlandC4Sigma = {3.0 / 4.0, 9.0 / (4.0 * kPi), 495.0 / (256.0 * kPi)};
}  // namespace

WendlandC4Kernel::WendlandC4Kernel(int dimension, Real h)
    : Kernel(dimension, h, 2.0, kWendlandC4Sigma, "smoothing_length"), oneD_(dimension == 1) {}

// With s = 1 - q/2:
//   1-D:    f = s^5 (2 q^2 + 5/2 q + 1),      f'/q = -7/2 s^4 (2 q + 1),
//           f'' = 7/4 s^3 (12 q^2 - 3 q - 2)
//   2-/3-D: f = s^6 (35/12 q^2 + 3 q + 1),    f'/q = -7/3 s^5 (5 q + 2),
//           f'' = 7/6 s^4 (35 q^2 - 8 q - 4)
Real WendlandC4Kernel::shape(Real q) const { return WendlandC4Profile{oneD_}.shape(q); }

Real WendlandC4Kernel::slopeOverQ(Real q) const { return WendlandC4Profile{oneD_}.slopeOverQ(q); }

Kernel::Curvature WendlandC4Kernel::curvature(Real q) const {
  if (q >= 2.0) return {0.0, 0.0};
  const Real s = 1.0 - 0.5 * q;
  const Real s2 = s * s;
  if (oneD_) return {-3.5 * s2 * s2 * (2.0 * q + 1.0), 1.75 * s2 * s * ((12.0 * q - 3.0) * q - 2.0)};
  return {-7.0 / 3.0 * s2 * s2 * s * (5.0 * q + 2.0), 7.0 / 6.0 * s2 * s2 * ((35.0 * q - 8.0) * q - 4.0)};
}

}  // namespace mfwave
