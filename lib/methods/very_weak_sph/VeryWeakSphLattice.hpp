#pragma once
// The very weak SPH on a box lattice stored as stencils per row type (issue 18).
//
// Every variant's rows depend only on where a particle sits relative to the box faces (the
// lattice is uniform and the boundary terms are per face), so the operator of a large box is the
// operator of a compact box of 2 depth + 1 nodes per axis with its middle row repeated. The
// compact box is assembled by the method itself (VeryWeakSphProblem with sparse storage: same
// variant, kernel, ghosts, faces, dashpots), its rows become the stencil table (LatticeStencils),
// and the depth is the smallest for which an assembly two nodes longer per axis is reproduced to
// round-off (1e-12 relative). No formula is written twice, and no step holds N x neighbours.

#include "lattice/LatticeStencils.hpp"
#include "methods/very_weak_sph/VeryWeakSphProblem.hpp"

#include <array>
#include <string>
#include <vector>

namespace mfwave {

template <int D>
struct VeryWeakSphStencils {
  LatticeStencils<D> mass, damping, stiffness;  // damping empty without transmitting faces
  LatticeStencils<D> smoothing;                 // S of eq. (33) on every component; empty without the filter
  LatticeStencils<D> deconvolution;             // eq. (35) on every component; empty without it
  // Per entry of settings.faceTractions: the nodal force of its traction at unit history, D
  // values per row type.
  std::vector<std::vector<Real>> faceLoads;
  // Per face carrying a surface patch of a kernel variant (index: BoxFace; empty for the others):
  // the force on every node from a unit traction on the face's facet of each node, G_ab =
  // T(a, facet of b on the face), so that a patch load is G (weight_b t).
  std::vector<LatticeStencils<D>> patchFaces;
  Real mismatch = 0;  // against the check assembly (0 when the compact box is the whole box)
};

// The nodes per axis of the lattice of settings.lower, settings.upper, settings.spacing. Throws what
// latticeIntervals throws.
template <int D>
std::array<Index, D> latticeNodesOf(const VeryWeakSphProblemSettings<D>& settings);

// The nodes per axis of the lattice of settings.lower, settings.upper, settings.spacing, after
// checking that the physical particles are that lattice in makeLattice's order (x fastest). Throws
// InputError("method.operator") naming the first particle that is not.
template <int D>
std::array<Index, D> checkedLatticeNodes(const ParticleSet<D>& particles, const VeryWeakSphProblemSettings<D>& settings);

// The stencils of `settings` on a lattice of `nodes` per axis. Throws InputError("method.operator")
// when no depth up to maxDepth reproduces the check assembly.
template <int D>
VeryWeakSphStencils<D> veryWeakSphStencils(const VeryWeakSphProblemSettings<D>& settings,
                                           const std::array<Index, D>& nodes, Index maxDepth = 8);

}  // namespace mfwave
