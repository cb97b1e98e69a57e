#pragma once
// What an updated-Lagrangian SPH case of the lamb2d or lamb3d study runs with (LambSolidCase.hpp): the
// method's options and the amplitude at which the large-deformation method answers the linear
// problem.

#include "methods/updated_lagrangian_sph/UpdatedLagrangianSphOptions.hpp"
#include "wiring/UpdatedLagrangianSphSpec.hpp"

namespace mfwave::lamb3d {

struct LambSolidSpec {
  // UpdatedLagrangianSphOptions' defaults (cubic spline, h / dx = 1.3, continuity density, gamma = 1,
  // no artificial stress, no XSPH, courant 0.3) except the material (the scene's) and what the
  // driver's keys set: the artificial viscosity (method.viscosity_alpha = 1, _beta = 0) and the
  // kernel-gradient correction (method.kernel_gradient_correction = true). Why: LambSolidCase.hpp.
  UpdatedLagrangianSphOptions options;
  // eps: the traction is eps times the scene's and the recorded probes are divided by eps, so the
  // strains (~ eps) stay in the linear range of the EOS and the Jaumann rate (method.ul_amplitude).
  Real amplitude = 1e-4;
  // The particles' volumes (so masses m = rho0 V) are their tributary areas (2-D): dx^2 inside, dx^2 / 2
  // on a face, dx^2 / 4 at a corner, or volumes (3-D): dx^3 inside, halved once per face a particle
  // lies on (edges dx^3 / 4, corners dx^3 / 8): the lattice's nodes lie on the faces
  // (method.ul_tributary_volumes).
  bool tributaryVolumes = true;

  // The lamb2d and lamb3d defaults for `material` (measured on lamb2d; lamb3d keeps them: LambSolidCase.hpp).
  static LambSolidSpec linearDefaults(const Material& material) {
    LambSolidSpec spec;
    spec.options = smallAmplitudeWaveOptions(material);  // the keys' defaults, declared once
    return spec;
  }
};

}  // namespace mfwave::lamb3d
