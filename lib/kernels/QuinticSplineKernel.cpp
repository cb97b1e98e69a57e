#include "kernels/QuinticSplineKernel.hpp"

#include "kernels/KernelProfiles.hpp"

#include <array>
#include <cmath>

namespace mfwave {

namespace {

// 1 / (S_d int_0^3 q^{d-1} f dq): 1/120, 7/(478 pi), 1/(120 pi); checked by quadrature in the tests.
constexpr std::array<Real, 3> kQuinticSplineSigma = {1.0 / 120.0, 7.0 / (478.0 * kPi), 1.0 / (120.0 * kPi)};

}  // namespace

QuinticSplineKernel::QuinticSplineKernel(int dimension, Real h)
    : Kernel(dimension, h, 3.0, kQuinticSplineSigma, "smoothing_length") {}

Real QuinticSplineKernel::shape(Real q) const { return QuinticSplineProfile{}.shape(q); }

// f'/q from its expanded polynomial on the inner piece (KernelProfiles.hpp says why).
Real QuinticSplineKernel::slopeOverQ(Real q) const { return QuinticSplineProfile{}.slopeOverQ(q); }

// f'' = 20 (3-q)^3 - 120 (2-q)^3 + 300 (1-q)^3 (no cancellation problem: f''(0) = -120).
Kernel::Curvature QuinticSplineKernel::curvature(Real q) const {
  if (q >= 3.0) return {0.0, 0.0};
  const Real t3 = 3.0 - q;
  Real second = 20.0 * t3 * t3 * t3;
  if (q < 2.0) {
    const Real t2 = 2.0 - q;
    second -= 120.0 * t2 * t2 * t2;
  }
  if (q < 1.0) {
    const Real t1 = 1.0 - q;
    second += 300.0 * t1 * t1 * t1;
  }
  return {slopeOverQ(q), second};
}

}  // namespace mfwave
