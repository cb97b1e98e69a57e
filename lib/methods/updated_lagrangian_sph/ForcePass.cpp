#include "methods/updated_lagrangian_sph/ForcePass.hpp"

#include "methods/updated_lagrangian_sph/PairSweep.hpp"

namespace mfwave {

template <int D>
void forceRates(const ParticleView<D>& view, const ForceInputs<D>& inputs, const ForceOutputs<D>& outputs,
                std::vector<PairSums<D>>& sums) {
  const Index n = view.count;
  // Each pair once, in an order that does not depend on the threads (PairSweep.hpp).
  pair_sweep::sumPairs<D, false, true>(view, false, &inputs, sums);
#pragma omp parallel for if (n > kParallelParticles) schedule(static)
  for (Index i = 0; i < n; ++i) pair_sweep::writeForce(view, sums[static_cast<std::size_t>(i)], i, outputs);
}

template void forceRates<1>(const ParticleView<1>&, const ForceInputs<1>&, const ForceOutputs<1>&,
                            std::vector<PairSums<1>>&);
template void forceRates<2>(const ParticleView<2>&, const ForceInputs<2>&, const ForceOutputs<2>&,
                            std::vector<PairSums<2>>&);
template void forceRates<3>(const ParticleView<3>&, const ForceInputs<3>&, const ForceOutputs<3>&,
                            std::vector<PairSums<3>>&);

}  // namespace mfwave
