#pragma once
// One row of the velocity-gradient pass (KinematicsPass.hpp has the equations): the pair sums of
// particle i and the rates written from them. Shared by the separate pass (KinematicsPass.cpp) and
// the fused pass of rhs (FusedPass.cpp), so both sum the same terms in the same order.

#include "methods/updated_lagrangian_sph/AlwaysInline.hpp"
#include "methods/updated_lagrangian_sph/JaumannStressRate.hpp"
#include "methods/updated_lagrangian_sph/KinematicsPass.hpp"
#include "methods/updated_lagrangian_sph/StressVoigt.hpp"

namespace mfwave {

template <int D>
struct KinematicsRow {
  Mat<D> gradient = Mat<D>::Zero();
  Vec<D> smoothing = Vec<D>::Zero();
  Real densityRate = 0;

  // The pair i, j: Vj = m_j / rho_j, vji = v_j - v_i, gradW = grad_i W_ij as row i uses it
  // (C_i grad_i W_ij when corrected), smoothingWeight = 2 W_ij / (rho_i + rho_j) (read only with XSPH).
  MFWAVE_ALWAYS_INLINE void add(Real mj, Real Vj, const Vec<D>& vji, const Vec<D>& gradW, Real smoothingWeight,
                                bool xsph) {
    gradient.noalias() += Vj * vji * gradW.transpose();  // Li eq. (22)
    densityRate -= mj * vji.dot(gradW);                             // Li eq. (18)
    if (xsph) smoothing += (mj * smoothingWeight) * vji;  // m_j / rhobar_ij W_ij (v_j - v_i)
  }

  // dx_i/dt (with XSPH), drho_i/dt and ds_i/dt (Li eq. 24-26) into qdot.
  void write(const ParticleView<D>& view, Index i, const KinematicsSettings& settings,
             const UpdatedLagrangianSphLayout<D>& layout, Real* qdot) const {
    constexpr int S = UpdatedLagrangianSphLayout<D>::stressComponents;
    const Vec<D> vi = view.velocity(i);
    for (int a = 0; a < D; ++a) qdot[layout.position(i, a)] = vi[a] + settings.xsph * smoothing[a];
    qdot[layout.density(i)] = settings.continuity ? densityRate : 0.0;
    const Mat<D> s = stressFromVoigt<D>(view.s + i * S);
    stressToVoigt<D>(jaumannStressRate<D>(gradient, s, settings.shearModulus), qdot + layout.stress(i, 0));
  }
};

}  // namespace mfwave
