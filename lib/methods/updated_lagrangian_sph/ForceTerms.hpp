#pragma once
// One row of the force pass (ForcePass.hpp has the equations): the pair sums of particle i and the
// outputs written from them. Shared by the separate pass (ForcePass.cpp) and the fused pass of rhs
// (FusedPass.cpp), so both sum the same terms in the same order.

#include "methods/updated_lagrangian_sph/AlwaysInline.hpp"
#include "methods/updated_lagrangian_sph/ArtificialStress.hpp"
#include "methods/updated_lagrangian_sph/ForcePass.hpp"

#include <algorithm>
#include <cmath>

namespace mfwave {

template <int D>
class ForceRow {
 public:
  ForceRow(const ParticleView<D>& view, const ForceInputs<D>& inputs, Index i)
      : view_(view), inputs_(inputs), i_(i) {}

  // The pair i, j: r = x_ij, vij = v_i - v_j, gradW = grad_i W_ij, correctedGradW = C_i grad_i W_ij
  // (gradW itself without the correction), stressWeight = f_ij^n (read only with the artificial stress).
  MFWAVE_ALWAYS_INLINE void add(Index j, const Vec<D>& r, const Vec<D>& vij, const Vec<D>& gradW,
                                const Vec<D>& correctedGradW, Real stressWeight) {
    const ArtificialViscosity& viscosity = inputs_.viscosity;
    const Mat<D>* A = inputs_.stressOverRho2;
    const Real* P = inputs_.pressureOverRho2;
    const Index i = i_;
    const Real mj = view_.m[j];
    Real pi = 0;
    if (viscosity.active()) {
      const Real mu = viscosity.mu(vij.dot(r), r.squaredNorm());
      if (mu != 0) {
        pi = viscosity.pi(mu, 0.5 * (inputs_.soundSpeed[i] + inputs_.soundSpeed[j]), 0.5 * (view_.rho[i] + view_.rho[j]));
        largestMu_ = std::max(largestMu_, std::abs(mu));
      }
    }
    // Li eq. (30); corrected: A_i C_i grad W + A_j C_j grad W (ForcePass.hpp).
    const Mat<D>* AC = inputs_.correctedStressOverRho2;
    Vec<D> force = AC != nullptr ? Vec<D>(AC[i] * gradW + AC[j] * gradW) : Vec<D>((A[i] + A[j]) * gradW);
    force -= pi * gradW;
    if (inputs_.artificialStress != nullptr) {
      const Vec<D> extra = stressWeight * ((inputs_.artificialStress[i] + inputs_.artificialStress[j]) * gradW);
      force += extra;
      artificialWork_ += mj * vij.dot(extra);
    }
    acceleration_ += mj * force;
    const Real vDotGrad = vij.dot(gradW);
    velocityMoment_.noalias() += mj * vij * correctedGradW.transpose();
    pressureWork_ += mj * (P[i] + P[j] + pi) * vDotGrad;
    viscousWork_ += mj * pi * vDotGrad;
  }

  void write(const ForceOutputs<D>& outputs) const {
    const Mat<D>* A = inputs_.stressOverRho2;
    const Real* P = inputs_.pressureOverRho2;
    const Index i = i_;
    for (int a = 0; a < D; ++a) outputs.acceleration[i * D + a] = acceleration_[a];
    if (inputs_.correctedStressOverRho2 != nullptr) {
      outputs.energyRate[i] =
          -(A[i].cwiseProduct(velocityMoment_)).sum() + 0.5 * viscousWork_ - 0.5 * artificialWork_;
    } else {
      // s_i / rho_i^2 = A_i + P_i I.
      Mat<D> deviatorOverRho2 = A[i];
      deviatorOverRho2.diagonal().array() += P[i];
      outputs.energyRate[i] =
          -(deviatorOverRho2.cwiseProduct(velocityMoment_)).sum() + 0.5 * pressureWork_ - 0.5 * artificialWork_;  // eq. (29)
    }
    outputs.viscousPower[i] = 0.5 * view_.m[i] * viscousWork_;
    outputs.artificialStressPower[i] = 0.5 * view_.m[i] * artificialWork_;
    outputs.largestMu[i] = largestMu_;
  }

 private:
  const ParticleView<D>& view_;
  const ForceInputs<D>& inputs_;
  Index i_;
  Vec<D> acceleration_ = Vec<D>::Zero();
  Mat<D> velocityMoment_ = Mat<D>::Zero();  // sum_j m_j v_ij (C_i) grad W^T
  Real pressureWork_ = 0;                   // sum_j m_j (P_i + P_j + Pi_ij) v_ij . grad W
  Real viscousWork_ = 0;                    // sum_j m_j Pi_ij v_ij . grad W
  Real artificialWork_ = 0;                 // sum_j m_j v_ij . T_ij grad W
  Real largestMu_ = 0;
};

}  // namespace mfwave
