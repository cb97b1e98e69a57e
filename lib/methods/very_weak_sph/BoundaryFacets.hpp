#pragma once
// Boundary facets and their statistical areas, Ding-Long-Wu eqs. (20), (26)-(27).
//
// A physical particle on m box faces (face, edge, corner) carries m facets, one per face, each with
// that face's outward unit normal and its own area A. The boundary sum of a facet on face k runs
// over the neighbours lying in the plane of face k: physical particles of that face and, when ghost
// layers are present, the ghosts in the same plane beyond the edges, which complete the sum.

#include "core/Types.hpp"
#include "kernels/Kernel.hpp"
#include "neighbours/NeighbourList.hpp"
#include "particles/ParticleSet.hpp"

#include <vector>

namespace mfwave {

template <int D>
struct BoundaryFacets {
  // Facets of physical particle a: [offsets[a], offsets[a + 1]); physicalCount() + 1 entries.
  std::vector<Index> offsets;
  std::vector<Index> particle;       // owning particle of each facet
  std::vector<int> face;             // its box face (BoxFace numbering)
  std::vector<Vec<D>> normal;        // outward unit normal of the face
  std::vector<Real> areaFraction;    // FA of eq. (26)
  std::vector<Real> planeSum;        // sum_{b in M_a^Y} W_ab over the facet's plane
  std::vector<Real> area;            // A of eq. (27): FA / (S planeSum)

  Index count() const { return static_cast<Index>(particle.size()); }
  Index begin(Index a) const { return offsets[static_cast<std::size_t>(a)]; }
  Index end(Index a) const { return offsets[static_cast<std::size_t>(a) + 1]; }
};

// S of eq. (20): S int_plane W dS = 1, from the kernel's plane integral (10h/7 for the 3-D cubic
// spline, eq. (40)).
Real surfaceScale(const Kernel& kernel);

// The facets of every physical boundary particle with their areas A = FA / (S sum_{M^Y} W),
// eqs. (20) and (27). areaCorrection = false gives FA = 1 (eq. (20)); with it FA = 2^{1-m} per facet
// of a particle on m faces (1 face, 1/2 edge, 1/4 corner). A neighbour lies in the facet's plane
// when its coordinate along the face's axis is within 1e-6 h of the particle's.
template <int D>
BoundaryFacets<D> boundaryFacets(const ParticleSet<D>& particles, const NeighbourList& neighbours,
                                 const Kernel& kernel, bool areaCorrection);

}  // namespace mfwave
