#pragma once
// The nodes and collocation rows of strong-form collocation on a solid the scene describes (issue
// 48): the lattice nodes of the scene's box well inside the solid, points on the solid's own
// surfaces, and the box's nodes where the solid meets the box. Nc = Ns: each node is a collocation
// point.
//
//   interior nodes     lattice nodes x = lower + dx i strictly inside the box with d(x) <= -gap dx
//                      (d the signed distance to the solid's own surfaces): rho u'' - L u = f
//   surface nodes      points on the solid's surfaces: each lattice cell the surface may cut gives
//                      the projection of its centre onto the surface, x <- x - d(x) n(x) (three
//                      times: exact on planes and balls, converging on the CSG's faces); a point
//                      closer than `minimum` dx to one kept before it (lattice order) is dropped,
//                      and so is one closer than gap dx to a box face (the box's corner nodes
//                      hold the solid there). Traction rows sigma(u) n = h with n the surface's
//                      outward normal there (Luo-Liu-Huang eq. (13)), or u = 0 where the solid
//                      says the surface is clamped.
//   box nodes          lattice nodes on the box's faces with d(x) <= 0: traction rows with the
//                      face's normal where the node is on one face only and that face is free,
//                      u = 0 otherwise.
//
// Why the gap: an interior node closer than about half a spacing to a surface node gives the RK
// moment matrices near-coincident points and the constrained operator a large eigenvalue (a small
// stable step); lattice nodes within gap dx of the surface are left to the surface nodes.
// The surface points' spacing lies between `minimum` dx and about dx (a cut cell every dx or so
// along the surface); each records it (the distance to its nearest surface neighbour), which a
// load uses as the node's share of the surface (its tributary length in 2-D).

#include "core/Types.hpp"
#include "methods/collocation/CollocationSystem.hpp"

#include <functional>
#include <vector>

namespace mfwave {

template <int D>
struct CollocationSolid {
  std::function<Real(const Vec<D>&)> distance;   // the solid's own surfaces (box faces excluded), < 0 inside
  std::function<Vec<D>(const Vec<D>&)> normal;   // unit outward normal of the surface nearest x
  Vec<D> lower = Vec<D>::Zero(), upper = Vec<D>::Zero();  // the box
  unsigned freeFaces = 0;                        // box faces (BoxFace bits) with traction rows
  // Surface points held fixed (u = 0: displacement rows in place of traction rows); empty: none.
  std::function<bool(const Vec<D>&)> clamped;
};

template <int D>
struct SolidCollocationNodes {
  Coordinates<D> nodes;               // interior, then box, then surface nodes
  CollocationPoints<D> points;        // one per node, in the same order
  std::vector<Real> surfaceSpacing;   // per node: the spacing of a surface node, 0 for the others
  Index interior = 0, box = 0, surface = 0;

  Index size() const { return static_cast<Index>(points.size()); }
  Vec<D> position(Index i) const { return points.points[static_cast<std::size_t>(i)]; }
  bool onSurface(Index i) const { return surfaceSpacing[static_cast<std::size_t>(i)] > 0; }
};

// Throws InputError("geometry.spacing") when dx does not divide the box and InputError("geometry.solid")
// when no interior node is left (a solid without surfaces of its own, the box, has no surface nodes).
template <int D>
SolidCollocationNodes<D> solidCollocationNodes(const CollocationSolid<D>& solid, Real dx, Real gap = 0.5,
                                               Real minimum = 0.6);

extern template SolidCollocationNodes<2> solidCollocationNodes<2>(const CollocationSolid<2>&, Real, Real, Real);
extern template SolidCollocationNodes<3> solidCollocationNodes<3>(const CollocationSolid<3>&, Real, Real, Real);

}  // namespace mfwave
