#pragma once
// Hypoelastic stress rate with the Jaumann (co-rotational) derivative, Li eq. (24)-(26).
//
// Index convention: L_ab = d v_a / d x_b (row = velocity component, column = derivative), which is
// what eq. (22) gives with grad v = sum_j V_j (v_j - v_i) (x) grad_i W_ij read as the outer product
// (v_j - v_i) grad W^T. Then
//   strain rate  eps' = (L + L^T) / 2            eq. (24)
//   spin         Omega = (L - L^T) / 2           eq. (25)
//   ds/dt = 2G (eps' - tr(eps') I / 3) + Omega s + s Omega^T = 2G dev(eps') + Omega s - s Omega   eq. (26)
// Why this sign: a rigid rotation x(t) = R(t) X carries v = Rdot R^T x, so L = Omega = Rdot R^T,
// and a stress that rotates with the body, s(t) = R s0 R^T, has ds/dt = Omega s + s Omega^T. The
// primer's eq. (23) writes grad v transposed (row = derivative); with that order the same formula
// would need the spin with the opposite sign. tests/methods/updated_lagrangian_sph/
// JaumannRotationTest.cpp checks that R^T s R stays s0 for a rotating block.
//
// The trace is the 3-D one (tr / 3) in every dimension: 2-D is plane strain (eps'_zz = 0) and
// 1-D uniaxial strain, so a 1-D bar has ds_xx/dt = (4G/3) eps'_xx and carries waves at c_p.

#include "core/Types.hpp"

namespace mfwave {

template <int D>
inline Mat<D> jaumannStressRate(const Mat<D>& velocityGradient, const Mat<D>& s, Real shearModulus) {
  const Mat<D> strainRate = 0.5 * (velocityGradient + velocityGradient.transpose());  // eq. (24)
  const Mat<D> spin = 0.5 * (velocityGradient - velocityGradient.transpose());        // eq. (25)
  Mat<D> rate = (2 * shearModulus) * strainRate;
  rate.diagonal().array() -= (2 * shearModulus / 3) * strainRate.trace();
  rate.noalias() += spin * s - s * spin;  // eq. (26): Omega s + s Omega^T
  return rate;
}

}  // namespace mfwave
