#pragma once
// Particles of a scene's geometry: the lattice of the box plus the optional ghost layers.

#include "io/scene/GeometrySpec.hpp"
#include "particles/ParticleSet.hpp"

namespace mfwave {

// D must equal geometry.dimension (std::invalid_argument otherwise).
template <int D>
ParticleSet<D> buildParticles(const GeometrySpec& geometry);

}  // namespace mfwave
