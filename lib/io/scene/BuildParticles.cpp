#include "io/scene/BuildParticles.hpp"

#include "particles/GhostLayers.hpp"
#include "particles/Lattice.hpp"

#include <stdexcept>
#include <string>

namespace mfwave {

template <int D>
ParticleSet<D> buildParticles(const GeometrySpec& geometry) {
  if (geometry.dimension != D)
    throw std::invalid_argument("buildParticles<" + std::to_string(D) + "> called for a " +
                                std::to_string(geometry.dimension) + "-D geometry");
  const Vec<D> lower = Eigen::Map<const Vec<D>>(geometry.lower.data());
  const Vec<D> upper = Eigen::Map<const Vec<D>>(geometry.upper.data());
  ParticleSet<D> particles = makeLattice<D>(lower, upper, geometry.spacing);
  if (geometry.ghostLayers > 0 && geometry.ghostFaces != 0)
    addGhostLayers<D>(particles, lower, upper, geometry.spacing, geometry.ghostLayers, geometry.ghostFaces);
  return particles;
}

template ParticleSet<1> buildParticles<1>(const GeometrySpec&);
template ParticleSet<2> buildParticles<2>(const GeometrySpec&);
template ParticleSet<3> buildParticles<3>(const GeometrySpec&);

}  // namespace mfwave
