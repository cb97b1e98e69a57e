#pragma once
// How far an operator's rows read: the halo depth of a rank's share (lib/decomposition) and the
// neighbourhood a part of a lattice needs (a surface patch's load, VeryWeakSphProblem).

#include "lattice/LatticeStencils.hpp"

#include <algorithm>
#include <array>
#include <cstdlib>

namespace mfwave {

// The largest |offset| along each axis over the stencils' entries.
template <int D, int C>
std::array<Index, D> stencilReach(const LatticeStencils<D, C>& stencils) {
  std::array<Index, D> reach{};
  for (Index e = 0; e < stencils.entryCount(); ++e)
    for (std::size_t s = 0; s < static_cast<std::size_t>(D); ++s)
      reach[s] = std::max(reach[s], static_cast<Index>(std::abs(stencils.offset(e)[s])));
  return reach;
}

}  // namespace mfwave
