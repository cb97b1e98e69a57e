#pragma once
// [method] options of the very weak form SPH (name = "very_weak_sph"), registered by the drivers
// that run it (addVeryWeakSphKeys) and read after the common sections. Every boundary correction,
// the dashpot lumping, the conservative smoothing and the deconvolution of Ding-Long-Wu is a key,
// so that its effect can be measured from the scene alone.

#include "io/scene/SceneReader.hpp"
#include "io/scene/SceneSchema.hpp"
#include "methods/very_weak_sph/VeryWeakSphOptions.hpp"

#include <string>
#include <vector>

namespace mfwave {

struct VeryWeakSphSpec {
  std::string kernel = "cubic_spline";   // kernelNames()
  Real smoothingLengthRatio = 1;         // h / dx
  // The variant (method.variant: galerkin, the default, symmetric and stable by construction;
  // consistent; published), the material and the four correction switches.
  VeryWeakSphOptions options;
  DashpotLumping dashpotLumping = DashpotLumping::Particle;  // published variant: eq. (32) or "consistent"
  Real smoothingRate = 0;                // 1/s; per step alpha = 1 - exp(-rate dt) (eq. 33)
  int smoothingOrder = 1;                // 1: eq. (33); 2: v <- v - alpha (I - S)^2 v
  bool smoothingScalesWithSpacing = false;  // rate given at geometry.spacing, scaled as 1 / dx
  bool deconvolution = true;             // report probes sharpened by eq. (35)
  // method.operator: "auto" (the lattice stencils where they can run the scene, else the sparse
  // matrices), "lattice" or "sparse" (issue 18).
  std::string operatorStorage = "auto";

  std::string variantName() const { return veryWeakSphVariantName(options.variant); }

  // The smoothing rate at lattice spacing dx, for a scene whose geometry.spacing is dx0.
  Real smoothingRateAt(Real dx, Real dx0) const {
    return smoothingScalesWithSpacing ? smoothingRate * dx0 / dx : smoothingRate;
  }
};

// Adds "very_weak_sph" to method.name and its option keys.
void addVeryWeakSphKeys(SceneSchema& schema);

// The option keys addVeryWeakSphKeys registered in `schema` (method.variant, method.kernel, ...; not
// method.name), for a driver that runs another method on a scene written for this one and accepts
// them unused (lamb2d's RK collocation).
std::vector<std::string> veryWeakSphOptionKeys(const SceneSchema& schema);

// Reads the options when method.name is very_weak_sph; `material` from the scene's [material].
VeryWeakSphSpec readVeryWeakSph(SceneReader& reader, const Material& material);

}  // namespace mfwave
