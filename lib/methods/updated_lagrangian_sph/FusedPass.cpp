#include "methods/updated_lagrangian_sph/FusedPass.hpp"

#include "methods/updated_lagrangian_sph/PairSweep.hpp"

namespace mfwave {

template <int D>
void fusedRates(const ParticleView<D>& view, const KinematicsSettings& settings,
                const UpdatedLagrangianSphLayout<D>& layout, Real* qdot, const ForceInputs<D>& inputs,
                const ForceOutputs<D>& outputs, std::vector<PairSums<D>>& sums) {
  const Index n = view.count;
  // Each pair once, in an order that does not depend on the threads (PairSweep.hpp).
  pair_sweep::sumPairs<D, true, true>(view, settings.xsph > 0, &inputs, sums);
#pragma omp parallel for if (n > kParallelParticles) schedule(static)
  for (Index i = 0; i < n; ++i) {
    const PairSums<D>& row = sums[static_cast<std::size_t>(i)];
    pair_sweep::writeKinematics(view, row, i, settings, layout, qdot);
    pair_sweep::writeForce(view, row, i, outputs);
  }
}

template void fusedRates<1>(const ParticleView<1>&, const KinematicsSettings&, const UpdatedLagrangianSphLayout<1>&,
                            Real*, const ForceInputs<1>&, const ForceOutputs<1>&, std::vector<PairSums<1>>&);
template void fusedRates<2>(const ParticleView<2>&, const KinematicsSettings&, const UpdatedLagrangianSphLayout<2>&,
                            Real*, const ForceInputs<2>&, const ForceOutputs<2>&, std::vector<PairSums<2>>&);
template void fusedRates<3>(const ParticleView<3>&, const KinematicsSettings&, const UpdatedLagrangianSphLayout<3>&,
                            Real*, const ForceInputs<3>&, const ForceOutputs<3>&, std::vector<PairSums<3>>&);

}  // namespace mfwave
