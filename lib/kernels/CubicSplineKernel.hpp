#pragma once
// Monaghan's M4 cubic spline, support 2h (Li primer eq. (8); Ding-Long-Wu eq. (38)).
// The standard SPH kernel: C2, compact, cheap; its Hessian is what the very weak form uses.

#include "kernels/Kernel.hpp"

namespace mfwave {

class CubicSplineKernel final : public Kernel {
 public:
  CubicSplineKernel(int dimension, Real h);

  const char* name() const override { return "cubic_spline"; }
  Real shape(Real q) const override;
  Real slopeOverQ(Real q) const override;
  Curvature curvature(Real q) const override;
  std::vector<Real> pieceBreaks() const override { return {0.0, 1.0, 2.0}; }
};

}  // namespace mfwave
