#include "methods/updated_lagrangian_sph/FusedPass.hpp"

#include "methods/updated_lagrangian_sph/ForceTerms.hpp"
#include "methods/updated_lagrangian_sph/KinematicsTerms.hpp"
#include "methods/updated_lagrangian_sph/ParallelThreshold.hpp"

namespace mfwave {

template <int D>
void fusedRates(const ParticleView<D>& view, const KinematicsSettings& settings,
                const UpdatedLagrangianSphLayout<D>& layout, Real* qdot, const ForceInputs<D>& inputs,
                const ForceOutputs<D>& outputs) {
  const Index n = view.count;
  const PairTable& pairs = *view.pairs;
  const bool xsph = settings.xsph > 0;
  const bool artificialStress = inputs.artificialStress != nullptr;
  // Gather form: row i only writes particle i's rates, so the result does not depend on threads.
#pragma omp parallel for if (n > kParallelParticles) schedule(static)
  for (Index i = 0; i < n; ++i) {
    const Vec<D> vi = view.velocity(i);
    KinematicsRow<D> kinematics;
    ForceRow<D> force(view, inputs, i);
    view.forEachPair(i, [&](Index k, Index j, const Vec<D>& r, const Vec<D>& gradW) MFWAVE_INLINE_LAMBDA {
      const Vec<D> correctedGradW = view.correctedGradient(i, gradW);
      const Real smoothingWeight = xsph ? pairs.smoothingWeight[static_cast<std::size_t>(k)] : 0.0;
      const Real stressWeight = artificialStress ? pairs.stressWeight[static_cast<std::size_t>(k)] : 0.0;
      const Vec<D> vji = view.velocity(j) - vi;
      kinematics.add(view.m[j], view.volume[j], vji, correctedGradW, smoothingWeight, xsph);
      force.add(j, r, Vec<D>(-vji), gradW, correctedGradW, stressWeight);  // -(v_j - v_i) is v_i - v_j exactly
    });
    kinematics.write(view, i, settings, layout, qdot);
    force.write(outputs);
  }
}

template void fusedRates<1>(const ParticleView<1>&, const KinematicsSettings&, const UpdatedLagrangianSphLayout<1>&,
                            Real*, const ForceInputs<1>&, const ForceOutputs<1>&);
template void fusedRates<2>(const ParticleView<2>&, const KinematicsSettings&, const UpdatedLagrangianSphLayout<2>&,
                            Real*, const ForceInputs<2>&, const ForceOutputs<2>&);
template void fusedRates<3>(const ParticleView<3>&, const KinematicsSettings&, const UpdatedLagrangianSphLayout<3>&,
                            Real*, const ForceInputs<3>&, const ForceOutputs<3>&);

}  // namespace mfwave
