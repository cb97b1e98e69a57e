#include "methods/very_weak_sph/BoundaryFacets.hpp"

#include "core/Error.hpp"
#include "kernels/PlaneIntegral.hpp"
#include "methods/very_weak_sph/StatisticalVolume.hpp"
#include "particles/BoxFace.hpp"

#include <cmath>

namespace mfwave {

Real surfaceScale(const Kernel& kernel) {
  // Ding-Long-Wu eq. (20): S_a int_plane W(x^a - y) dS_y = 1.
  return 1.0 / planeIntegralThroughCentre(kernel);
}

template <int D>
BoundaryFacets<D> boundaryFacets(const ParticleSet<D>& particles, const NeighbourList& neighbours,
                                 const Kernel& kernel, bool areaCorrection) {
  checkVeryWeakInputs(particles, neighbours, kernel);
  const Index n = particles.physicalCount();
  const Real scale = surfaceScale(kernel);
  const Real tolerance = 1e-6 * kernel.smoothingLength();

  BoundaryFacets<D> facets;
  facets.offsets.assign(static_cast<std::size_t>(n) + 1, 0);
  for (Index a = 0; a < n; ++a)
    facets.offsets[static_cast<std::size_t>(a) + 1] = facets.offsets[static_cast<std::size_t>(a)] + particles.facetCount(a);
  const auto total = static_cast<std::size_t>(facets.offsets.back());
  facets.particle.resize(total);
  facets.face.resize(total);
  facets.normal.resize(total);
  facets.areaFraction.resize(total);
  facets.planeSum.resize(total);
  facets.area.resize(total);

#pragma omp parallel for schedule(dynamic, 64)
  for (Index a = 0; a < n; ++a) {
    const int m = particles.facetCount(a);
    if (m == 0) continue;
    const std::uint8_t mask = particles.faceMask[static_cast<std::size_t>(a)];
    const Vec<D> xa = particles.position(a);
    auto f = static_cast<std::size_t>(facets.offsets[static_cast<std::size_t>(a)]);
    for (int k = 0; k < 2 * D; ++k) {
      if ((mask & faceBit(k)) == 0) continue;
      const int axis = faceAxis(k);
      // M_a^Y of eq. (20): neighbours in the plane of face k (ghosts there complete the sum).
      Real sum = 0;
      for (Index b : neighbours.row(a)) {
        const Vec<D> xb = particles.position(b);
        if (std::abs(xb[axis] - xa[axis]) <= tolerance) sum += kernel.value(Vec<D>(xa - xb));
      }
      // Eq. (26): the fraction of the tangent-plane support lying on the surface.
      const Real fraction = areaCorrection ? std::ldexp(1.0, 1 - m) : 1.0;
      facets.particle[f] = a;
      facets.face[f] = k;
      facets.normal[f] = faceNormal<D>(k);
      facets.areaFraction[f] = fraction;
      facets.planeSum[f] = sum;
      facets.area[f] = fraction / (scale * sum);  // eq. (27)
      ++f;
    }
  }
  return facets;
}

template BoundaryFacets<1> boundaryFacets<1>(const ParticleSet<1>&, const NeighbourList&, const Kernel&, bool);
template BoundaryFacets<2> boundaryFacets<2>(const ParticleSet<2>&, const NeighbourList&, const Kernel&, bool);
template BoundaryFacets<3> boundaryFacets<3>(const ParticleSet<3>&, const NeighbourList&, const Kernel&, bool);

}  // namespace mfwave
