#include "methods/very_weak_sph/StatisticalVolume.hpp"

#include "core/Error.hpp"

#include <cmath>
#include <string>

namespace mfwave {

template <int D>
void checkVeryWeakInputs(const ParticleSet<D>& particles, const NeighbourList& neighbours, const Kernel& kernel) {
  if (kernel.dimension() != D)
    throw InputError("dimension", "the kernel is " + std::to_string(kernel.dimension()) + "-D, the particles " +
                                      std::to_string(D) + "-D");
  if (neighbours.rowCount() < particles.physicalCount())
    throw InputError("neighbours", "the neighbour list has no row for some physical particles");
  if (!neighbours.indices.empty() && neighbours.offsets.back() != neighbours.totalCount())
    throw InputError("neighbours", "the neighbour list is inconsistent");
}

template <int D>
std::vector<Real> volumeFractions(const ParticleSet<D>& particles, bool correction) {
  const auto n = static_cast<std::size_t>(particles.physicalCount());
  std::vector<Real> fraction(n, 1.0);
  if (!correction) return fraction;
  // Ding-Long-Wu eq. (24): the part of the support inside the box; a lattice box face halves it.
  for (std::size_t a = 0; a < n; ++a)
    fraction[a] = std::ldexp(1.0, -particles.facetCount(static_cast<Index>(a)));
  return fraction;
}

template <int D>
std::vector<Real> shepardSums(const ParticleSet<D>& particles, const NeighbourList& neighbours,
                              const Kernel& kernel) {
  checkVeryWeakInputs(particles, neighbours, kernel);
  const Index n = particles.physicalCount();
  std::vector<Real> sums(static_cast<std::size_t>(n), 0.0);
#pragma omp parallel for schedule(static)
  for (Index a = 0; a < n; ++a) {
    const Vec<D> xa = particles.position(a);
    Real sum = 0;
    for (Index b : neighbours.row(a)) sum += kernel.value(Vec<D>(xa - particles.position(b)));
    sums[static_cast<std::size_t>(a)] = sum;
  }
  return sums;
}

template <int D>
std::vector<Real> statisticalVolumes(const ParticleSet<D>& particles, const NeighbourList& neighbours,
                                     const Kernel& kernel, bool volumeCorrection) {
  // Ding-Long-Wu eqs. (4), (25): V_a = FV_a / sum_{b in M_a} W_ab.
  std::vector<Real> volume = shepardSums(particles, neighbours, kernel);
  const std::vector<Real> fraction = volumeFractions(particles, volumeCorrection);
  for (std::size_t a = 0; a < volume.size(); ++a) volume[a] = fraction[a] / volume[a];
  return volume;
}

#define MFWAVE_INSTANTIATE(D)                                                                                \
  template void checkVeryWeakInputs<D>(const ParticleSet<D>&, const NeighbourList&, const Kernel&);          \
  template std::vector<Real> volumeFractions<D>(const ParticleSet<D>&, bool);                                \
  template std::vector<Real> shepardSums<D>(const ParticleSet<D>&, const NeighbourList&, const Kernel&);     \
  template std::vector<Real> statisticalVolumes<D>(const ParticleSet<D>&, const NeighbourList&, const Kernel&, \
                                                   bool);
MFWAVE_INSTANTIATE(1)
MFWAVE_INSTANTIATE(2)
MFWAVE_INSTANTIATE(3)
#undef MFWAVE_INSTANTIATE

}  // namespace mfwave
