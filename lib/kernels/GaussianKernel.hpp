#pragma once
// Gaussian kernel f = exp(-q^2) cut at q = 3 (Li primer eq. (7)).
//
// Normalisation: eq. (7) uses sigma_d = pi^{-d/2}, which normalises the untruncated Gaussian. Cut
// at q = 3 it would integrate to erf(3) (1-D), 1 - e^{-9} (2-D), erf(3) - 6/sqrt(pi) e^{-9} (3-D),
// short of 1 by 2e-5 .. 4.4e-4. We divide by that truncated mass so the kernel reproduces
// constants exactly like the compact splines do; the value jump of e^{-9} ~ 1.2e-4 at the cut is
// kept (no shift), so f matches eq. (7) inside the support up to that constant factor.

#include "kernels/Kernel.hpp"

namespace mfwave {

class GaussianKernel final : public Kernel {
 public:
  GaussianKernel(int dimension, Real h);

  const char* name() const override { return "gaussian"; }
  Real shape(Real q) const override;
  Real slopeOverQ(Real q) const override;
  Curvature curvature(Real q) const override;
  // Not polynomial: quadrature subdivides the single piece.
  std::vector<Real> pieceBreaks() const override { return {0.0, 3.0}; }
};

}  // namespace mfwave
