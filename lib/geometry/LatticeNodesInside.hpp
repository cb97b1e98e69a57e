#pragma once
// The lattice nodes origin + dx * i inside a solid or on its surface, for the lattice methods,
// which put one particle on every such node (the surface ones carry the boundary conditions).
// "On" allows 1e-9 dx for rounding: a box face through a row of nodes keeps the row.

#include "core/Types.hpp"
#include "geometry/Solid.hpp"

#include <array>
#include <vector>

namespace mfwave {

template <int D>
struct InsideNodes {
  std::vector<std::array<Index, D>> node;  // integer lattice coordinates i
  std::vector<Vec<D>> position;            // origin + dx * i
  Index size() const { return static_cast<Index>(node.size()); }
};

// In lattice order (x fastest). Throws InputError "spacing", "origin" or "solid" (unbounded) as
// LatticeWindow does.
template <int D>
InsideNodes<D> latticeNodesInside(const Solid<D>& solid, Real dx, const Vec<D>& origin);

}  // namespace mfwave
