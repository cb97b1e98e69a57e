#include "methods/updated_lagrangian_sph/KinematicsPass.hpp"

#include "methods/updated_lagrangian_sph/KinematicsTerms.hpp"
#include "methods/updated_lagrangian_sph/ParallelThreshold.hpp"

namespace mfwave {

template <int D>
void kinematicsRates(const ParticleView<D>& view, const KinematicsSettings& settings,
                     const UpdatedLagrangianSphLayout<D>& layout, Real* qdot) {
  const Index n = view.count;
  const PairTable& pairs = *view.pairs;
  const NeighbourList& list = *view.neighbours;
  const bool xsph = settings.xsph > 0;
  // Gather form: row i only writes particle i's rates, so the result does not depend on threads.
#pragma omp parallel for if (n > kParallelParticles) schedule(static)
  for (Index i = 0; i < n; ++i) {
    const Vec<D> vi = view.velocity(i);
    KinematicsRow<D> row;
    const Vec<D> xi = view.position(i);
    const Index last = list.offsets[static_cast<std::size_t>(i) + 1];
    for (Index k = list.offsets[static_cast<std::size_t>(i)]; k < last; ++k) {
      if (!pairs.used(k)) continue;  // i itself, or listed through the skin but outside the support
      const Index j = list.indices[static_cast<std::size_t>(k)];
      const Vec<D> r = xi - view.position(j);
      const Vec<D> gradW = view.correctedGradient(i, Vec<D>(pairs.gradientFactor[static_cast<std::size_t>(k)] * r));
      const Real smoothingWeight = xsph ? pairs.smoothingWeight[static_cast<std::size_t>(k)] : 0.0;
      row.add(view.m[j], view.volume[j], Vec<D>(view.velocity(j) - vi), gradW, smoothingWeight, xsph);
    }
    row.write(view, i, settings, layout, qdot);
  }
}

template void kinematicsRates<1>(const ParticleView<1>&, const KinematicsSettings&,
                                 const UpdatedLagrangianSphLayout<1>&, Real*);
template void kinematicsRates<2>(const ParticleView<2>&, const KinematicsSettings&,
                                 const UpdatedLagrangianSphLayout<2>&, Real*);
template void kinematicsRates<3>(const ParticleView<3>&, const KinematicsSettings&,
                                 const UpdatedLagrangianSphLayout<3>&, Real*);

}  // namespace mfwave
