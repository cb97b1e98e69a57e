#pragma once
// Cubic B-spline window of the reproducing-kernel collocation method (Luo-Liu-Huang eq. (6)):
// phi(z) = 2/3 - 4 z^2 + 4 z^3 (z <= 1/2), 4/3 (1 - z)^3 (1/2 < z <= 1), 0 beyond, z = |r| / a.
//
// It is the cubic spline of CubicSplineKernel with h = a/2, times 2/3, but the RK literature
// parameterises it by the support radius a, so here the profile length is a itself (q = z,
// supportFactor() = 1, smoothingLength() = supportRadius() = a). The normalisation makes it
// integrate to 1 like every kernel here; the RK shape functions do not depend on it.

#include "kernels/Kernel.hpp"

namespace mfwave {

class CubicBSplineKernel final : public Kernel {
 public:
  // a > 0 is the support radius (InputError key "support_radius").
  CubicBSplineKernel(int dimension, Real supportRadius);

  const char* name() const override { return "cubic_b_spline"; }
  Real shape(Real z) const override;
  Real slopeOverQ(Real z) const override;
  Curvature curvature(Real z) const override;
  std::vector<Real> pieceBreaks() const override { return {0.0, 0.5, 1.0}; }
};

}  // namespace mfwave
