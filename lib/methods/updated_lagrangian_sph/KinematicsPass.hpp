#pragma once
// The velocity-gradient pass: everything the configuration rate dq/dt = (dx/dt, drho/dt, ds/dt)
// needs, from positions, velocities, densities and stresses only (no pressures, no forces), so the
// leapfrog's drift costs one pass over the pairs (those of the view's pair table, which holds grad W
// and W). The per-pair terms are in KinematicsTerms.hpp; rhs sums them in the same sweep as the
// forces (FusedPass.hpp). Each unordered pair is evaluated once and added to both rows (PairSweep.hpp).
//   L_i = sum_j V_j (v_j - v_i) grad_i W_ij^T, V_j = m_j / rho_j     Li eq. (22), L_ab = dv_a/dx_b
//   ds_i/dt = 2G dev(eps'_i) + Omega_i s_i - s_i Omega_i              Li eq. (24)-(26)
//   drho_i/dt = sum_j m_j (v_i - v_j) . grad_i W_ij                   Li eq. (18), continuity only
//   dx_i/dt = v_i + xsph sum_j m_j / rhobar_ij (v_j - v_i) W_ij       XSPH (Monaghan 1989)
// With the kernel-gradient correction (view.correction), grad_i W_ij is C_i grad_i W_ij in the
// velocity gradient and the continuity equation. Constraints are applied by the caller.

#include "methods/updated_lagrangian_sph/PairSums.hpp"
#include "methods/updated_lagrangian_sph/ParticleView.hpp"
#include "methods/updated_lagrangian_sph/UpdatedLagrangianSphLayout.hpp"

#include <vector>

namespace mfwave {

struct KinematicsSettings {
  Real shearModulus = 1;
  Real xsph = 0;
  bool continuity = true;  // false: drho/dt = 0 (summation density)
};

// Writes the rates of x, rho and s into qdot (layout.configurationSize() entries, layout order).
// sums: scratch, one per particle (resized).
template <int D>
void kinematicsRates(const ParticleView<D>& view, const KinematicsSettings& settings,
                     const UpdatedLagrangianSphLayout<D>& layout, Real* qdot, std::vector<PairSums<D>>& sums);

extern template void kinematicsRates<1>(const ParticleView<1>&, const KinematicsSettings&,
                                        const UpdatedLagrangianSphLayout<1>&, Real*, std::vector<PairSums<1>>&);
extern template void kinematicsRates<2>(const ParticleView<2>&, const KinematicsSettings&,
                                        const UpdatedLagrangianSphLayout<2>&, Real*, std::vector<PairSums<2>>&);
extern template void kinematicsRates<3>(const ParticleView<3>&, const KinematicsSettings&,
                                        const UpdatedLagrangianSphLayout<3>&, Real*, std::vector<PairSums<3>>&);

}  // namespace mfwave
