#pragma once
// Morris's quintic spline, support 3h: f = (3-q)^5 - 6 (2-q)^5 + 15 (1-q)^5, each term only where
// its base is positive. C4, so its Hessian is smoother than the cubic spline's, at 1.5x the reach.

#include "kernels/Kernel.hpp"

namespace mfwave {

class QuinticSplineKernel final : public Kernel {
 public:
  QuinticSplineKernel(int dimension, Real h);

  const char* name() const override { return "quintic_spline"; }
  Real shape(Real q) const override;
  Real slopeOverQ(Real q) const override;
  Curvature curvature(Real q) const override;
  std::vector<Real> pieceBreaks() const override { return {0.0, 1.0, 2.0, 3.0}; }
};

}  // namespace mfwave
