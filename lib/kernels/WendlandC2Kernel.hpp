#pragma once
// Wendland C2 kernel, support 2h. Wendland functions are positive definite only up to the
// dimension they were built for, so 1-D uses the 1-D function (1 - q/2)^3 (3/2 q + 1) and 2-D/3-D
// use (1 - q/2)^4 (2 q + 1). Its positive Fourier transform avoids the pairing instability.

#include "kernels/Kernel.hpp"

namespace mfwave {

class WendlandC2Kernel final : public Kernel {
 public:
  WendlandC2Kernel(int dimension, Real h);

  const char* name() const override { return "wendland_c2"; }
  Real shape(Real q) const override;
  Real slopeOverQ(Real q) const override;
  Curvature curvature(Real q) const override;
  std::vector<Real> pieceBreaks() const override { return {0.0, 2.0}; }

 private:
  bool oneD_;
};

}  // namespace mfwave
