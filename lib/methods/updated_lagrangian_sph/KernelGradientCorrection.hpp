#pragma once
// The kernel-gradient correction of Randles and Libersky (1996) / Bonet and Lok (1999): a matrix
// C_i per particle such that the corrected gradient C_i grad_i W_ij differentiates every linear
// field exactly,
//   M_i = sum_j V_j (x_j - x_i) grad_i W_ij^T,   C_i = M_i^{-T},
//   so sum_j V_j (f_j - f_i) (C_i grad_i W_ij)^T = grad f  for f linear.
// Without it the velocity gradient (Li eq. 22) reads a lattice sum that is not the identity
// (1.0105 at h = 1.3 dp in 2-D) and, at a free surface, misses the half of the support that lies
// outside the body, so the surface fibres of a bent plate see too small a strain rate.
// A particle whose M_i is near singular (too few neighbours, a fragment: an entry of M_i^{-1} above
// 10) keeps C_i = I.

#include "methods/updated_lagrangian_sph/ParticleView.hpp"

namespace mfwave {

// Fills correction[i] = C_i for every particle of the view, from its pair table.
template <int D>
void kernelGradientCorrection(const ParticleView<D>& view, Mat<D>* correction);

extern template void kernelGradientCorrection<1>(const ParticleView<1>&, Mat<1>*);
extern template void kernelGradientCorrection<2>(const ParticleView<2>&, Mat<2>*);
extern template void kernelGradientCorrection<3>(const ParticleView<3>&, Mat<3>*);

}  // namespace mfwave
