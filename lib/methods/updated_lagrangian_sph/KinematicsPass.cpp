#include "methods/updated_lagrangian_sph/KinematicsPass.hpp"

#include "methods/updated_lagrangian_sph/KinematicsTerms.hpp"
#include "methods/updated_lagrangian_sph/ParallelThreshold.hpp"

namespace mfwave {

template <int D>
void kinematicsRates(const ParticleView<D>& view, const KinematicsSettings& settings,
                     const UpdatedLagrangianSphLayout<D>& layout, Real* qdot) {
  const Index n = view.count;
  const PairTable& pairs = *view.pairs;
  const bool xsph = settings.xsph > 0;
  // Gather form: row i only writes particle i's rates, so the result does not depend on threads.
#pragma omp parallel for if (n > kParallelParticles) schedule(static)
  for (Index i = 0; i < n; ++i) {
    const Vec<D> vi = view.velocity(i);
    KinematicsRow<D> row;
    view.forEachPair(i, [&](Index k, Index j, const Vec<D>&, const Vec<D>& gradW) MFWAVE_INLINE_LAMBDA {
      const Real smoothingWeight = xsph ? pairs.smoothingWeight[static_cast<std::size_t>(k)] : 0.0;
      row.add(view.m[j], view.volume[j], Vec<D>(view.velocity(j) - vi), view.correctedGradient(i, gradW),
              smoothingWeight, xsph);
    });
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
