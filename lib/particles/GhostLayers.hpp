#pragma once
// Ghost particles outside chosen faces of a lattice box.
//
// Why: a kernel sum at a particle near the boundary misses the part of its support that lies
// outside the body. Ghost particles fill that part, so boundary conditions can be imposed by
// giving the ghosts suitable values (mirror, extrapolation) while the interior stencil is kept.
// The ghosts are all lattice points outside the box within `layers` spacings of it on the
// chosen sides, including the edge and corner regions between two or three chosen faces: a
// support of radius up to layers*dx around any particle on the surface is then complete.

#include "core/Types.hpp"
#include "particles/BoxFace.hpp"
#include "particles/ParticleSet.hpp"

#include <cstdint>

namespace mfwave {

// Appends the ghost layers to `set` (kind Ghost, faceMask 0, volume dx^D, fresh global ids
// from set.nextGlobalId()) and returns how many were added. `faces` is a BoxFace mask
// (faceBit(BoxFace::MinusX) | ..., or allFaces(D)); the box and spacing are validated as by
// makeLattice. Throws InputError("ghost_layers", ...) for layers < 0 and
// InputError("ghost_faces", ...) for face bits that a D-dimensional box does not have.
// The lattice is extended with the same node formula as makeLattice, so ghosts continue the
// physical lattice exactly.
template <int D>
Index addGhostLayers(ParticleSet<D>& set, const Vec<D>& lower, const Vec<D>& upper, Real dx,
                     int layers, std::uint8_t faces);

// How many ghosts addGhostLayers adds for the same arguments (and the same checks), without
// building them: what a rank of a split run reports for a lattice it does not hold whole.
template <int D>
Index ghostLayerCount(const Vec<D>& lower, const Vec<D>& upper, Real dx, int layers, std::uint8_t faces);

}  // namespace mfwave
