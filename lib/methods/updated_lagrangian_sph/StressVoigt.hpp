#pragma once
// The deviatoric stress s between its Voigt storage in the state vector (UpdatedLagrangianSphLayout:
// 1-D xx; 2-D xx, yy, xy; 3-D xx, yy, zz, yz, xz, xy) and a symmetric D x D matrix, and the full
// 3-D contraction s:s that the stored energy needs.
//
// Below 3-D the stored components are completed by the kinematic assumption of the method:
// 2-D plane strain keeps s traceless, so s_zz = -(s_xx + s_yy); 1-D uniaxial strain is isotropic
// across the bar, so s_yy = s_zz = -s_xx / 2.

#include "core/Types.hpp"

namespace mfwave {

template <int D>
inline Mat<D> stressFromVoigt(const Real* s) {
  Mat<D> m;
  if constexpr (D == 1) {
    m(0, 0) = s[0];
  } else if constexpr (D == 2) {
    m << s[0], s[2], s[2], s[1];
  } else {
    m << s[0], s[5], s[4], s[5], s[1], s[3], s[4], s[3], s[2];
  }
  return m;
}

// Stores the symmetric part of m (m is expected to be symmetric already).
template <int D>
inline void stressToVoigt(const Mat<D>& m, Real* s) {
  if constexpr (D == 1) {
    s[0] = m(0, 0);
  } else if constexpr (D == 2) {
    s[0] = m(0, 0);
    s[1] = m(1, 1);
    s[2] = 0.5 * (m(0, 1) + m(1, 0));
  } else {
    s[0] = m(0, 0);
    s[1] = m(1, 1);
    s[2] = m(2, 2);
    s[3] = 0.5 * (m(1, 2) + m(2, 1));
    s[4] = 0.5 * (m(0, 2) + m(2, 0));
    s[5] = 0.5 * (m(0, 1) + m(1, 0));
  }
}

// s:s of the full 3-D deviator, including the components implied below 3-D (see above).
template <int D>
inline Real deviatoricContraction(const Real* s) {
  if constexpr (D == 1) {
    return 1.5 * s[0] * s[0];  // s_xx^2 + 2 (s_xx / 2)^2
  } else if constexpr (D == 2) {
    const Real zz = -(s[0] + s[1]);
    return s[0] * s[0] + s[1] * s[1] + zz * zz + 2 * s[2] * s[2];
  } else {
    return s[0] * s[0] + s[1] * s[1] + s[2] * s[2] + 2 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]);
  }
}

}  // namespace mfwave
