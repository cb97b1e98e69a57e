#pragma once
// The Monaghan-Gray artificial stress against the tensile instability (Monaghan 2000; Gray,
// Monaghan & Swift 2001), the R_ij of Li eq. (30):
//   R_ij = f_ij^n (R_i + R_j),  f_ij = W(r_ij) / W(dp),
// where R_i is built in the principal frame of the Cauchy stress sigma_i: with sigma_i = Q diag(l) Q^T,
//   R'_aa = -epsilon l_a / rho_i^2  where l_a > 0 (tension), 0 where l_a <= 0,   R_i = Q R' Q^T.
// R_i is symmetric and negative semi-definite: added to sigma / rho^2 in the momentum equation it
// is a repulsion between particles along the principal directions in tension, and it vanishes
// for compressive stress. In 2-D (plane strain) only the in-plane stress enters the momentum
// equation, so the principal frame is that of the in-plane 2 x 2 block.

#include "core/Types.hpp"

#include <cmath>

namespace mfwave {

// R_i of one particle.
template <int D>
Mat<D> artificialStressTensor(const Mat<D>& sigma, Real rho, Real epsilon);

// f_ij^n = (W(r_ij) / W(dp))^n from the kernel value at the pair distance.
inline Real artificialStressWeight(Real kernelValue, Real inverseReferenceValue, Real exponent) {
  const Real f = kernelValue * inverseReferenceValue;
  if (exponent == 4) {  // the usual choice: two multiplications instead of pow
    const Real f2 = f * f;
    return f2 * f2;
  }
  return std::pow(f, exponent);
}

extern template Mat<1> artificialStressTensor<1>(const Mat<1>&, Real, Real);
extern template Mat<2> artificialStressTensor<2>(const Mat<2>&, Real, Real);
extern template Mat<3> artificialStressTensor<3>(const Mat<3>&, Real, Real);

}  // namespace mfwave
