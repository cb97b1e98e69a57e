#pragma once
// Regular lattices of particles filling a line, a rectangle or a block, with the box faces
// tagged. Nodes sit at lower + i*dx for i = 0..L/dx on every axis, so both ends of each axis
// carry particles (boundary conditions are imposed on them) and there are L/dx + 1 per axis.
// The spacing must divide every side length: a lattice that does not reach the far face would
// silently move the boundary.

#include "core/Types.hpp"
#include "particles/BoxFace.hpp"
#include "particles/ParticleSet.hpp"

#include <array>
#include <cstdint>

namespace mfwave {

// Number of lattice intervals L/dx along each axis of the box [lower, upper] with spacing dx.
// Throws InputError("spacing", ...) for dx <= 0, non-finite dx, or a dx that does not divide a
// side (L/dx more than 1e-9 relative away from an integer), and InputError("geometry", ...)
// naming the axis when upper <= lower or a bound is not finite.
template <int D>
std::array<Index, D> latticeIntervals(const Vec<D>& lower, const Vec<D>& upper, Real dx);

// Physical particles on the lattice of [lower, upper] with spacing dx, x varying fastest.
// Coordinates are lower + (upper - lower) * i / n, which is lower + i*dx up to the 1e-9 the
// spacing check allows, and hits both ends exactly. Volumes are dx^D, global ids 0..N-1, and
// faceMask marks the faces each surface particle lies on.
template <int D>
ParticleSet<D> makeLattice(const Vec<D>& lower, const Vec<D>& upper, Real dx);
// The particles of the lattice's nodes [first, end) per axis (a rank's block), with the positions,
// face tags and global ids (x-fastest node numbers) the whole lattice gives them. Throws
// InputError("lattice") for a range outside the lattice or empty.
template <int D>
ParticleSet<D> makeLattice(const Vec<D>& lower, const Vec<D>& upper, Real dx, const std::array<Index, D>& first,
                           const std::array<Index, D>& end);

// The faces (faceBit mask) node `node` of a lattice with `intervals` per axis lies on: the lower
// face of an axis at index 0, the upper at index intervals. makeLattice tags its particles so.
template <int D>
std::uint8_t latticeFaceMask(const std::array<Index, D>& intervals, const std::array<Index, D>& node) {
  std::uint8_t faces = 0;
  for (int a = 0; a < D; ++a) {
    const auto s = static_cast<std::size_t>(a);
    if (node[s] == 0) faces |= faceBit(2 * a);
    if (node[s] == intervals[s]) faces |= faceBit(2 * a + 1);
  }
  return faces;
}

// The number (x fastest) of the lattice node nearest x, found per axis by the nodes' coordinates;
// on a tie the lower node, as a search over makeLattice's particles in their order finds it. Costs
// nothing per node, so a rank can place probes and point loads without the whole lattice.
template <int D>
Index nearestLatticeNode(const Vec<D>& lower, const Vec<D>& upper, Real dx, const Vec<D>& x);

ParticleSet<1> makeLine(Real x0, Real x1, Real dx);
ParticleSet<2> makeRectangle(const Vec2& lower, const Vec2& upper, Real dx);
ParticleSet<3> makeBlock(const Vec3& lower, const Vec3& upper, Real dx);

}  // namespace mfwave
