#pragma once
// A surface patch load (Ding-Long-Wu eqs. (36)-(37), PatchLoad.hpp) for the lattice storage, as
// nonzero entries computed from the patch's neighbourhood alone: the weights of the loaded face's
// nodes near the rectangle, and for the kernel variants the rows of G (weight_b t) that reach them
// (VeryWeakSphStencils::patchFaces, eq. (19)). Nothing whole-lattice sized is built, so a serial run
// and every rank of a split one (issue 22) get the same entries at the cost of the patch.

#include "lattice/LatticeStencils.hpp"
#include "methods/very_weak_sph/VeryWeakSphProblem.hpp"
#include "systems/SparseLoads.hpp"

#include <array>

namespace mfwave {

// The load of `patch` on the lattice of settings.lower, settings.upper, settings.spacing with `nodes`
// per axis: for the galerkin variant the exact int_patch W_a t of the tent kernel
// (patchTentWeights, patchNodalForce); for the kernel variants G (weight_b t) with the cell
// fractions (patchLoadWeights) and G = `faceStencils`, the stencils of the patch's face. Each row is
// summed in its stencil's entry order. Throws what patchLoadWeights throws for the patch.
template <int D>
SparseLoad latticePatchLoad(const VeryWeakSphProblemSettings<D>& settings, const PatchTraction<D>& patch,
                            const std::array<Index, D>& nodes, const LatticeStencils<D>* faceStencils);

}  // namespace mfwave
