#pragma once
// The part of one lattice cell inside a solid: its measure, first moment (for the centroid) and the
// area of the solid's surface inside the cell, by recursive subdivision.
//
// A (sub-)cell whose centre is farther from the surface than its half diagonal lies wholly on one
// side (the solid's signed distance never exceeds the true distance, Solid.hpp), so it is taken
// whole or skipped; any other is split into 2^D halves, down to `depth` levels. A cell still cut
// at the last level is cut by the plane tangent to the surface at the point nearest its centre
// (PlaneCut), which gives its volume and its area of surface; its moment is taken at its centre.
//
// Surface area is therefore the sum of tangent-plane pieces in the finest cut sub-cells: exact for
// flat faces, second order in the sub-cell size for curved ones. Where two faces meet at an edge or
// a corner the piece follows one of them (the nearest / active one), so the area within the
// sub-cells along the edge is off, either way, by up to about (edge length) x (finest side).

#include "core/Types.hpp"
#include "geometry/Solid.hpp"

namespace mfwave {

template <int D>
struct CellShare {
  Real volume = 0;
  Vec<D> moment = Vec<D>::Zero();  // integral of x over the inside part
  Real area = 0;                   // of the solid's surface inside the cell
};

// The share of the cell of centre `centre` and side `side` inside `solid`, subdividing at most
// `depth` times (side / 2^depth the finest).
template <int D>
CellShare<D> cellShare(const Solid<D>& solid, const Vec<D>& centre, Real side, int depth);

}  // namespace mfwave
