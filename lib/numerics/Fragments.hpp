#pragma once
// Objective measures of whether a body came through a collision or a load in one piece (the rings
// study's rings): the connected fragments of a 2-D particle cloud (particles closer than a link
// distance are joined), and the links of the body at the start that are now torn.

#include <utility>
#include <vector>

#include "core/Types.hpp"
#include "particles/ParticleSet.hpp"

namespace mfwave {

struct Fragments {
  std::vector<Index> label;  // per particle: its fragment, 0 = the largest, 1 = the next, ...
  std::vector<Index> sizes;  // particles per fragment, largest first
  Index count() const { return static_cast<Index>(sizes.size()); }
  // Particles outside the `keep` largest fragments (strays and small clumps).
  Index particlesOutsideLargest(Index keep) const;
};

// Connected components of the graph joining particles closer than `linkDistance`.
Fragments findFragments(const Coordinates<2>& positions, Real linkDistance);

// The pairs (i < j) closer than `linkDistance`: the links of the body at t = 0.
std::vector<std::pair<Index, Index>> linkPairs(const Coordinates<2>& positions, Real linkDistance);
// How many of `links` are now longer than `length`: torn open by a crack (an elastic ring stretches
// them by a few per cent; clumping shortens them).
Index tornLinks(const std::vector<std::pair<Index, Index>>& links, const Coordinates<2>& positions, Real length);

}  // namespace mfwave
