#include "methods/very_weak_sph/KernelCorrection.hpp"

#include "core/Error.hpp"
#include "methods/very_weak_sph/StatisticalVolume.hpp"

namespace mfwave {

template <int D>
std::vector<Real> kernelCorrectionFactors(const ParticleSet<D>& particles, const NeighbourList& neighbours,
                                          const Kernel& kernel, const std::vector<Real>& volumes, bool correction) {
  checkVeryWeakInputs(particles, neighbours, kernel);
  const Index n = particles.physicalCount();
  if (static_cast<Index>(volumes.size()) != n) throw InputError("volumes", "need one volume per physical particle");
  std::vector<Real> alpha(static_cast<std::size_t>(n), 1.0);
  if (!correction) return alpha;
#pragma omp parallel for schedule(static)
  for (Index a = 0; a < n; ++a) {
    const Vec<D> xa = particles.position(a);
    Real sum = 0;
    for (Index b : neighbours.row(a)) {
      if (b >= n) continue;  // ghosts carry no unknowns and no volume
      sum += kernel.value(Vec<D>(xa - particles.position(b))) * volumes[static_cast<std::size_t>(b)];
    }
    alpha[static_cast<std::size_t>(a)] = 1.0 / sum;  // Ding-Long-Wu eq. (29)
  }
  return alpha;
}

template std::vector<Real> kernelCorrectionFactors<1>(const ParticleSet<1>&, const NeighbourList&, const Kernel&,
                                                      const std::vector<Real>&, bool);
template std::vector<Real> kernelCorrectionFactors<2>(const ParticleSet<2>&, const NeighbourList&, const Kernel&,
                                                      const std::vector<Real>&, bool);
template std::vector<Real> kernelCorrectionFactors<3>(const ParticleSet<3>&, const NeighbourList&, const Kernel&,
                                                      const std::vector<Real>&, bool);

}  // namespace mfwave
