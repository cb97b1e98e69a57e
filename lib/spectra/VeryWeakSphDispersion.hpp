#pragma once
// The interior stencil of the very weak form SPH (Ding-Long-Wu) on a regular lattice, for the
// lattice dispersion analysis (numerics/LatticeDispersion.hpp): a block with ghost layers on every
// face (as in the paper's section 8), large enough that the centre particle's support and the
// supports of its neighbours see no boundary, assembled by assembleVeryWeakSph, and the centre row
// of the system. Results: docs/studies/vwsph-dispersion.md.

#include "numerics/LatticeDispersion.hpp"
#include "core/Material.hpp"

#include <string>
#include <vector>

namespace mfwave {

enum class VeryWeakSphDispersionVariant {
  Published,                 // the scheme as published (VeryWeakSphOptions defaults)
  PublishedRowSumCorrected,  // the published row with its self block corrected to sum to zero
  Consistent,                // VeryWeakSphVariant::Consistent
  Galerkin,                  // VeryWeakSphVariant::Galerkin (tent kernel; kernel and h / dx do not enter)
};

// "published", "published_row_sum", "consistent", "galerkin".
const std::vector<std::string>& veryWeakSphDispersionVariantNames();
const char* veryWeakSphDispersionVariantName(VeryWeakSphDispersionVariant variant);
// Throws InputError(key) for an unknown name.
VeryWeakSphDispersionVariant parseVeryWeakSphDispersionVariant(const std::string& name,
                                                               const std::string& key = "variant");

template <int D>
struct VeryWeakSphLatticeStencil {
  LatticeStencil<D> stencil;   // row of the centre particle: G_b = (alpha_a / rho) K_ab
  Index physicalParticles = 0; // of the block
  Index ghostParticles = 0;
  int halfWidth = 0;           // the block is [-halfWidth dx, halfWidth dx]^D
  int ghostLayers = 0;
  Real spacing = 0;
  Real smoothingLength = 0;
  // stencilDifference between the centre row and the row of its neighbour at +dx along x: ~1e-16
  // when the rows are interior (translation invariant).
  Real translationDifference = 0;
};

// The centre stencil of a lattice block at spacing dx with smoothing length ratio * dx (kernel by
// name, kernelNames(); the Galerkin variant's tent kernel ignores both, but the block is sized by
// them). Throws InputError("smoothing_length_ratio") for ratio <= 0, InputError("spacing") for
// spacing <= 0.
template <int D>
VeryWeakSphLatticeStencil<D> veryWeakSphInteriorStencil(VeryWeakSphDispersionVariant variant,
                                                        const std::string& kernelName, Real smoothingLengthRatio,
                                                        const Material& material, Real spacing = 1);

}  // namespace mfwave
