#pragma once
// Wendland C4 kernel, support 2h: 1-D (1 - q/2)^5 (2 q^2 + 5/2 q + 1), 2-D/3-D
// (1 - q/2)^6 (35/12 q^2 + 3 q + 1) (see WendlandC2Kernel.hpp for why 1-D differs).

#include "kernels/Kernel.hpp"

namespace mfwave {

class WendlandC4Kernel final : public Kernel {
 public:
  WendlandC4Kernel(int dimension, Real h);

  const char* name() const override { return "wendland_c4"; }
  Real shape(Real q) const override;
  Real slopeOverQ(Real q) const override;
  Curvature curvature(Real q) const override;
  std::vector<Real> pieceBreaks() const override { return {0.0, 2.0}; }

 private:
  bool oneD_;
};

}  // namespace mfwave
