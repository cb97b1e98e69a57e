#pragma once
// The velocity-gradient pass and the force pass in one sweep over the pairs, for rhs, where both
// parts of the rate are taken at the same state: each pair's velocity difference and (corrected)
// kernel gradient are read once for both. The equations are those of KinematicsPass.hpp and
// ForcePass.hpp; each unordered pair is evaluated once and its terms added to both rows, in the
// same order as the separate passes (PairSweep.hpp), so the rates equal those of the two passes. The force inputs (A_i, P_i, c_i, R_i, and
// A_i C_i with the correction) depend only on the state and are prepared before the sweep.

#include "methods/updated_lagrangian_sph/ForcePass.hpp"
#include "methods/updated_lagrangian_sph/KinematicsPass.hpp"

namespace mfwave {

// Writes the configuration rates into qdot (as kinematicsRates) and the force outputs (as forceRates).
template <int D>
void fusedRates(const ParticleView<D>& view, const KinematicsSettings& settings,
                const UpdatedLagrangianSphLayout<D>& layout, Real* qdot, const ForceInputs<D>& inputs,
                const ForceOutputs<D>& outputs, std::vector<PairSums<D>>& sums);

extern template void fusedRates<1>(const ParticleView<1>&, const KinematicsSettings&,
                                   const UpdatedLagrangianSphLayout<1>&, Real*, const ForceInputs<1>&,
                                   const ForceOutputs<1>&, std::vector<PairSums<1>>&);
extern template void fusedRates<2>(const ParticleView<2>&, const KinematicsSettings&,
                                   const UpdatedLagrangianSphLayout<2>&, Real*, const ForceInputs<2>&,
                                   const ForceOutputs<2>&, std::vector<PairSums<2>>&);
extern template void fusedRates<3>(const ParticleView<3>&, const KinematicsSettings&,
                                   const UpdatedLagrangianSphLayout<3>&, Real*, const ForceInputs<3>&,
                                   const ForceOutputs<3>&, std::vector<PairSums<3>>&);

}  // namespace mfwave
