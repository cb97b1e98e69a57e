#pragma once
// Read-only diagnostics of one state, as free functions of a ParticleView: the energy terms of
// UpdatedLagrangianSphEnergy and the zero-energy-mode indicator. The system gathers the view and
// the ledger; these do the sums.

#include "methods/updated_lagrangian_sph/EquationOfState.hpp"
#include "methods/updated_lagrangian_sph/ParticleView.hpp"
#include "methods/updated_lagrangian_sph/UpdatedLagrangianSph.hpp"

namespace mfwave {

// kinetic = sum 1/2 m |v|^2; internal = sum m e (e: count specific internal energies);
// strain = sum m_i [ s_i:s_i / (4 G rho_i) + c0^2 (ln(rho_i/rho0) + rho0/rho_i - 1) ]: the deviatoric
// energy of linear elasticity (s:s with the implied out-of-plane components, StressVoigt.hpp) and
// the exact stored energy of the gamma = 1 EOS (EquationOfState.hpp). The ledger entries are left
// 0. Sums run in index order, so they do not depend on the thread count.
template <int D>
UpdatedLagrangianSphEnergy stateEnergy(const ParticleView<D>& view, const Real* e, const StiffenedGasEos& eos,
                                       Real shearModulus);

// zigzag = sqrt(sum m |v_i - vbar_i|^2 / sum m |v_i|^2), vbar_i = sum_j V_j v_j W_ij / sum_j V_j W_ij
// (self included; 0 when all v = 0), its worst particle, and the smallest listed pair distance over
// `spacing` (infinity when no pair is listed).
template <int D>
ZeroEnergyModeIndicator zeroEnergyModeIndicator(const ParticleView<D>& view, Real spacing);

extern template UpdatedLagrangianSphEnergy stateEnergy<1>(const ParticleView<1>&, const Real*, const StiffenedGasEos&, Real);
extern template UpdatedLagrangianSphEnergy stateEnergy<2>(const ParticleView<2>&, const Real*, const StiffenedGasEos&, Real);
extern template UpdatedLagrangianSphEnergy stateEnergy<3>(const ParticleView<3>&, const Real*, const StiffenedGasEos&, Real);
extern template ZeroEnergyModeIndicator zeroEnergyModeIndicator<1>(const ParticleView<1>&, Real);
extern template ZeroEnergyModeIndicator zeroEnergyModeIndicator<2>(const ParticleView<2>&, Real);
extern template ZeroEnergyModeIndicator zeroEnergyModeIndicator<3>(const ParticleView<3>&, Real);

}  // namespace mfwave
