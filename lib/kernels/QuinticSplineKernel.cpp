#include "kernels/QuinticSplineKernel.hpp"

#include <array>
#include <cmath>

namespace mfwave {

namespace {

// 1 / (S_d int_0^3 q^{d-1} f dq): 1/120, 7/(478 pi), 1/(120 pi); checked by quadrature in the tests.
constexpr std::array<Real, 3> kSigma = {1.0 / 120.0, 7.0 / (478.0 * kPi), 1.0 / (120.0 * kPi)};

Real pow4(Real t) { return (t * t) * (t * t); }
Real pow5(Real t) { return pow4(t) * t; }

}  // namespace

QuinticSplineKernel::QuinticSplineKernel(int dimension, Real h)
    : Kernel(dimension, h, 3.0, kSigma, "smoothing_length") {}

Real QuinticSplineKernel::shape(Real q) const {
  if (q >= 3.0) return 0.0;
  Real f = pow5(3.0 - q);
  if (q < 2.0) f -= 6.0 * pow5(2.0 - q);
  if (q < 1.0) f += 15.0 * pow5(1.0 - q);
  return f;
}

// f' = -5 (3-q)^4 + 30 (2-q)^4 - 75 (1-q)^4. On the inner piece the three terms cancel to O(q),
// so f'/q is taken from its expanded polynomial -120 + 120 q^2 - 50 q^3 instead of dividing.
Real QuinticSplineKernel::slopeOverQ(Real q) const {
  if (q < 1.0) return -120.0 + q * q * (120.0 - 50.0 * q);
  if (q < 2.0) return (-5.0 * pow4(3.0 - q) + 30.0 * pow4(2.0 - q)) / q;
  if (q < 3.0) return -5.0 * pow4(3.0 - q) / q;
  return 0.0;
}

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
