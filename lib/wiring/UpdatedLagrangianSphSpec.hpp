#pragma once
// [method] options of the updated-Lagrangian SPH for solids (name = "updated_lagrangian_sph"),
// registered by the drivers that run it (addUpdatedLagrangianSphKeys) and read after the common
// sections. Every artificial term of the primer (viscosity, artificial stress, XSPH) and every
// step criterion is a key, with the defaults of UpdatedLagrangianSphOptions, so that its effect can
// be measured from the scene alone. These drivers integrate a first-order system: they also call
// useFirstOrderIntegrators (IntegratorSpec.hpp) for [integrator].

#include "io/scene/SceneReader.hpp"
#include "io/scene/SceneSchema.hpp"

#include <string>
#include "methods/updated_lagrangian_sph/UpdatedLagrangianSphOptions.hpp"

namespace mfwave {

// Adds "updated_lagrangian_sph" to method.name and its option keys. A schema holds the options of
// one SPH method: registering these after addVeryWeakSphKeys throws std::logic_error (method.kernel
// and method.smoothing_length_ratio are shared names with different defaults).
void addUpdatedLagrangianSphKeys(SceneSchema& schema);

// The one declaration of the UL-SPH's viscosity and gradient-correction keys (method.viscosity_alpha,
// method.viscosity_beta, method.kernel_gradient_correction), which addUpdatedLagrangianSphKeys
// registers with the method's defaults and a study that runs the method among others with its own
// (the Lamb study: alpha 1, the correction on; its scenes' other [method] keys are the very weak
// SPH's, so it registers these alone).
struct UpdatedLagrangianSphKeyDefaults {
  Real viscosityAlpha = 0.1;
  Real viscosityBeta = 0;
  bool kernelGradientCorrection = false;
  std::string alphaNote;  // appended to method.viscosity_alpha's description
};
void addUpdatedLagrangianSphViscosityKeys(SceneSchema& schema, const UpdatedLagrangianSphKeyDefaults& defaults);

// The defaults for elastic waves at small amplitude (the Lamb study, and mfwave plan of a scene run as
// it runs it): alpha 1, measured best on lamb2d.toml at every spacing (it damps the particle-scale
// ringing of the free surface; 0 and 0.1 ring, 2 is no better), and the kernel-gradient correction on.
UpdatedLagrangianSphKeyDefaults smallAmplitudeWaveDefaults();
// The method's options for elastic waves at small amplitude in `material`: the options' defaults
// with smallAmplitudeWaveDefaults' viscosity and correction (the Lamb study's, the solid study's).
UpdatedLagrangianSphOptions smallAmplitudeWaveOptions(const Material& material);

// Reads the options when method.name is updated_lagrangian_sph; `material` from the scene's
// [material]. method.body_force has scene.dimension entries or 3 (then those beyond the dimension
// must be 0); absent, it is zero.
UpdatedLagrangianSphOptions readUpdatedLagrangianSph(SceneReader& reader, const Material& material);

}  // namespace mfwave
