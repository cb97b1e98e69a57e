#pragma once
// Particles from a solid: one per lattice cell [x - dx/2, x + dx/2]^D (x = origin + dx * i) that
// meets the solid, carrying the measure of the cell's part inside the solid as its volume (a
// body-fitted fill: the volumes add up to the solid's, and the particles of cut cells sit where
// their material is).
//
// - Volume, centroid and surface area of each cell's inside part come from recursive subdivision
//   (CellShare): sub-cells classified by signed distance against their half diagonal, the finest
//   cut ones by the tangent plane. The default depth 3 (finest side dx / 8) is the shallowest that
//   keeps a ball of radius 3 dx within the 1e-3 the tests ask (measured 4e-4 in 3-D; radius 10 dx:
//   4e-5 in 3-D, 1e-5 in 2-D; depth 2 gives 1.7e-3 at radius 3 dx), at about 8 + 32 + 128 distance
//   evaluations per cut cell in 3-D; each further level divides the error by 4 and costs 4x.
//   Features thinner than two finest sub-cells are not resolved.
// - A particle sits on its node when its cell is wholly inside, at the centroid of the inside part
//   when the surface cuts the cell (moved onto the nearest surface should that centroid fall
//   outside, as it does for a cell around a hole smaller than the cell).
// - Slivers, cells with less than sliverFraction * dx^D inside, are not kept: their volume, first
//   moment and surface area go to the nearest kept particle (nearest by position), so the total
//   volume and area stay. A receiver that is itself cut moves to the centroid of the merged
//   material; one whose cell is whole stays on its node. A sliver is a poor quadrature point (it
//   carries almost no volume) and its centroid can sit close to a neighbour: on a ball of radius
//   10 dx in 3-D, keeping every cell leaves pairs 0.35 dx apart, the default 0.1 none closer than
//   0.6 dx with no volume above 1.1 dx^3 (0.3 would give 0.66 dx but volumes up to 1.6 dx^3).
// - Surface particles are those whose (merged) cells hold surface area: the cut cells, and whole
//   cells with a face of the solid on their boundary. Their normal is the solid's normal at the
//   surface point nearest the particle; their area is the sum of the tangent-plane pieces of their
//   finest cut sub-cells (CellShare: second order on curved surfaces, short or long by about
//   (edge length) x dx / 16 at sharp edges).

#include "core/Types.hpp"
#include "geometry/Solid.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace mfwave {

struct FillOptions {
  int depth = 3;              // subdivision levels below a cut cell (finest side dx / 2^depth)
  Real sliverFraction = 0.1;  // cells with less than this fraction of dx^D inside are merged
};

template <int D>
struct SolidParticles {
  std::vector<Vec<D>> position;
  std::vector<Real> volume;
  std::vector<std::uint8_t> surface;  // 1 for a surface particle
  std::vector<Vec<D>> normal;         // unit outward normal of a surface particle, zero otherwise
  std::vector<Real> area;             // surface area in a surface particle's cell(s), zero otherwise
  std::vector<std::array<Index, D>> cell;  // the lattice node of the particle's own cell

  Index size() const { return static_cast<Index>(volume.size()); }
};

// Particles in lattice order (x fastest). Throws InputError "spacing", "origin" or "solid"
// (unbounded, see LatticeWindow), "fill.depth" (outside 0..8) or "fill.sliver_fraction"
// (outside [0, 1)).
template <int D>
SolidParticles<D> fill(const Solid<D>& solid, Real dx, const Vec<D>& origin, const FillOptions& options = {});

}  // namespace mfwave
