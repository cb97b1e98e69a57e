#pragma once
// The lamb3d method on a block for the benchmarks: the very weak SPH's Galerkin variant on its
// lattice stencils, lambda = mu = rho = 1, h = dx, with dashpots on the faces `transmittingFaces`
// names (none: a free block). Shared by bench_very_weak_sph_lattice and the MPI programs.

#include "methods/very_weak_sph/VeryWeakSphProblem.hpp"

#include <array>
#include <cstdint>

namespace mfwave::bench {

inline VeryWeakSphProblemSettings<3> galerkinBlock(const std::array<Index, 3>& nodes, Real spacing,
                                                   std::uint8_t transmittingFaces) {
  VeryWeakSphProblemSettings<3> s;
  s.options.material = Material::fromLame(1, 1, 1);
  s.options.variant = VeryWeakSphVariant::Galerkin;
  s.spacing = spacing;
  s.smoothingLength = spacing;
  s.lower = Vec3::Zero();
  for (int a = 0; a < 3; ++a) s.upper[a] = spacing * static_cast<Real>(nodes[static_cast<std::size_t>(a)] - 1);
  s.transmittingFaces = transmittingFaces;
  s.storage = OperatorStorage::Lattice;
  return s;
}

}  // namespace mfwave::bench
