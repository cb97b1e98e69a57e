#include "methods/updated_lagrangian_sph/KinematicsPass.hpp"

#include "methods/updated_lagrangian_sph/PairSweep.hpp"

namespace mfwave {

template <int D>
void kinematicsRates(const ParticleView<D>& view, const KinematicsSettings& settings,
                     const UpdatedLagrangianSphLayout<D>& layout, Real* qdot, std::vector<PairSums<D>>& sums) {
  const Index n = view.count;
  // Each pair once, in an order that does not depend on the threads (PairSweep.hpp).
  pair_sweep::sumPairs<D, true, false>(view, settings.xsph > 0, nullptr, sums);
#pragma omp parallel for if (n > kParallelParticles) schedule(static)
  for (Index i = 0; i < n; ++i)
    pair_sweep::writeKinematics(view, sums[static_cast<std::size_t>(i)], i, settings, layout, qdot);
}

template void kinematicsRates<1>(const ParticleView<1>&, const KinematicsSettings&,
                                 const UpdatedLagrangianSphLayout<1>&, Real*, std::vector<PairSums<1>>&);
template void kinematicsRates<2>(const ParticleView<2>&, const KinematicsSettings&,
                                 const UpdatedLagrangianSphLayout<2>&, Real*, std::vector<PairSums<2>>&);
template void kinematicsRates<3>(const ParticleView<3>&, const KinematicsSettings&,
                                 const UpdatedLagrangianSphLayout<3>&, Real*, std::vector<PairSums<3>>&);

}  // namespace mfwave
