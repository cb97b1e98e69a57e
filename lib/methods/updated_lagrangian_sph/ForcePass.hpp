#pragma once
// The force pass: everything the momentum rate dp/dt = (dv/dt, de/dt, ledger) needs, in one pass
// over the pairs of the view's pair table (grad W and W from there, not from the kernel). The
// per-pair terms are in PairSweep.hpp; rhs sums them in the same sweep as the velocity gradient
// (FusedPass.hpp). With A_i = sigma_i / rho_i^2 (sigma = s - p I, Li eq. 28), P_i = p_i / rho_i^2,
// v_ij = v_i - v_j and the pair tensor M_ij = A_i + A_j - Pi_ij I + f_ij^n (R_i + R_j):
//   dv_i/dt = sum_j m_j M_ij grad_i W_ij (+ body force and loads, added by the caller)   Li eq. (30)
//   de_i/dt = -(s_i / rho_i^2) : sum_j m_j v_ij grad_i W_ij^T
//             + 1/2 sum_j m_j (P_i + P_j + Pi_ij) v_ij . grad_i W_ij
//             - 1/2 sum_j m_j v_ij . f_ij^n (R_i + R_j) grad_i W_ij                         Li eq. (29)
// Each pair term is antisymmetric in i, j (M_ij symmetric, grad_i W_ij odd), so sum_i m_i dv_i/dt
// vanishes to round-off. The energy equation is the exact counterpart of the momentum equation:
// its deviatoric work uses the velocity gradient with m_j / rho_i in place of V_j (the two agree to
// O(grad rho)), and the artificial stress, which the primer leaves out of eq. (29), is put in like
// Pi_ij, so that d/dt (kinetic + internal) = 0 pair by pair. The ledger rates are the per-particle
// halves of the pair powers:
//   viscous   1/2 m_i sum_j m_j Pi_ij v_ij . grad_i W_ij                (>= 0: Pi_ij > 0 only when approaching)
//   R work    1/2 m_i sum_j m_j v_ij . f_ij^n (R_i + R_j) grad_i W_ij  (the power of R on the motion)
// With the kernel-gradient correction C_i (KernelGradientCorrection.hpp) the stress term becomes
// A_i C_i grad_i W_ij + A_j C_j grad_i W_ij, and the energy equation uses the same corrected
// velocity gradient as the stress rate:
//   de_i/dt = -A_i : sum_j m_j v_ij (C_i grad_i W_ij)^T + 1/2 sum_j m_j Pi_ij v_ij . grad_i W_ij - (R work)
// The pair terms stay antisymmetric (momentum is conserved) and balance the kinetic energy pair by
// pair; angular momentum is conserved only to the order of the correction (Bonet and Lok 1999).
// Viscosity and artificial stress keep the plain gradient.

#include "methods/updated_lagrangian_sph/ArtificialViscosity.hpp"
#include "methods/updated_lagrangian_sph/PairSums.hpp"
#include "methods/updated_lagrangian_sph/ParticleView.hpp"

#include <vector>

namespace mfwave {

template <int D>
struct ForceInputs {
  const Mat<D>* stressOverRho2 = nullptr;  // A_i = sigma_i / rho_i^2
  const Mat<D>* correctedStressOverRho2 = nullptr;  // A_i C_i with the correction (view.correction); else null
  const Real* pressureOverRho2 = nullptr;  // P_i = p_i / rho_i^2
  const Real* soundSpeed = nullptr;        // c_i of eq. (21), for Pi_ij
  const Mat<D>* artificialStress = nullptr;  // R_i; null when the artificial stress is off (f_ij^n: the pair table)
  ArtificialViscosity viscosity;
};

template <int D>
struct ForceOutputs {
  Real* acceleration = nullptr;           // count * D: the pair sum only
  Real* energyRate = nullptr;             // count
  Real* viscousPower = nullptr;           // count: particle i's share of the dissipation rate
  Real* artificialStressPower = nullptr;  // count
  Real* largestMu = nullptr;              // count: max |mu_ij| over i's pairs, for the time step
};

// sums: scratch, one per particle (resized). Each unordered pair is evaluated once (PairSweep.hpp).
template <int D>
void forceRates(const ParticleView<D>& view, const ForceInputs<D>& inputs, const ForceOutputs<D>& outputs,
                std::vector<PairSums<D>>& sums);

extern template void forceRates<1>(const ParticleView<1>&, const ForceInputs<1>&, const ForceOutputs<1>&,
                                   std::vector<PairSums<1>>&);
extern template void forceRates<2>(const ParticleView<2>&, const ForceInputs<2>&, const ForceOutputs<2>&,
                                   std::vector<PairSums<2>>&);
extern template void forceRates<3>(const ParticleView<3>&, const ForceInputs<3>&, const ForceOutputs<3>&,
                                   std::vector<PairSums<3>>&);

}  // namespace mfwave
