#pragma once
// One row of the velocity-gradient pass (KinematicsPass.hpp has the equations): the pair sums of
// particle i (summed pair by pair in PairSweep.hpp) and the rates written from them.

#include "methods/updated_lagrangian_sph/JaumannStressRate.hpp"
#include "methods/updated_lagrangian_sph/KinematicsPass.hpp"
#include "methods/updated_lagrangian_sph/StressVoigt.hpp"

namespace mfwave {

template <int D>
struct KinematicsRow {
  Mat<D> gradient = Mat<D>::Zero();   // L_i = sum_j V_j (v_j - v_i) (C_i grad_i W_ij)^T
  Vec<D> smoothing = Vec<D>::Zero();  // sum_j m_j 2 W_ij / (rho_i + rho_j) (v_j - v_i)
  Real densityRate = 0;               // sum_j m_j (v_i - v_j) . C_i grad_i W_ij

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
