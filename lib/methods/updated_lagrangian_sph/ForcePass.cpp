#include "methods/updated_lagrangian_sph/ForcePass.hpp"

#include "methods/updated_lagrangian_sph/ForceTerms.hpp"
#include "methods/updated_lagrangian_sph/ParallelThreshold.hpp"

namespace mfwave {

template <int D>
void forceRates(const ParticleView<D>& view, const ForceInputs<D>& inputs, const ForceOutputs<D>& outputs) {
  const Index n = view.count;
  const PairTable& pairs = *view.pairs;
  const bool artificialStress = inputs.artificialStress != nullptr;
  // Gather form: row i only writes particle i's outputs, so the result does not depend on threads.
#pragma omp parallel for if (n > kParallelParticles) schedule(static)
  for (Index i = 0; i < n; ++i) {
    const Vec<D> vi = view.velocity(i);
    ForceRow<D> row(view, inputs, i);
    view.forEachPair(i, [&](Index k, Index j, const Vec<D>& r, const Vec<D>& gradW) MFWAVE_INLINE_LAMBDA {
      const Real stressWeight = artificialStress ? pairs.stressWeight[static_cast<std::size_t>(k)] : 0.0;
      row.add(j, r, Vec<D>(vi - view.velocity(j)), gradW, view.correctedGradient(i, gradW), stressWeight);
    });
    row.write(outputs);
  }
}

template void forceRates<1>(const ParticleView<1>&, const ForceInputs<1>&, const ForceOutputs<1>&);
template void forceRates<2>(const ParticleView<2>&, const ForceInputs<2>&, const ForceOutputs<2>&);
template void forceRates<3>(const ParticleView<3>&, const ForceInputs<3>&, const ForceOutputs<3>&);

}  // namespace mfwave
