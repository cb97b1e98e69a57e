#pragma once
// The very weak form SPH problem a scene describes (VeryWeakSphProblem.hpp): the [method] keys,
// the lattice of the case, the [[boundary]] faces (traction, fixed, displacement, transmitting)
// and the surface-patch loads. lamb3d builds every case through it; a new study on another
// geometry gets the same set-up from its scene.

#include "io/scene/Scene.hpp"
#include "methods/very_weak_sph/VeryWeakSphProblem.hpp"
#include "wiring/VeryWeakSphSpec.hpp"

namespace mfwave {

// Refuses, before any work, what the very weak SPH cannot run with this scene: loads other than
// surface patches (InputError "load[i].type"), the smoothing filter or prescribed faces with an
// integrator other than central_difference (InputError "method.smoothing_rate" / "boundary"),
// deconvolution or smoothing with the galerkin variant ("method.deconvolution" /
// "method.smoothing_rate"), symmetry planes without the lattice storage ("method.operator"). `spec` is the case's (its smoothing rate may differ from the scene's).
// Called while the scene is read: the scene's own refusals go through `reader`, so they name the
// file and line of the key.
void checkVeryWeakSphScene(const SceneReader& reader, const Scene& scene, const VeryWeakSphSpec& spec,
                           const std::string& program);

// The problem settings of one case: `geometry` is the case's lattice (its spacing may differ from
// the scene's), `spec` its method options. `withBoundaries` false drops every [[boundary]] (all
// faces free: a reference case without dashpots). The settings point into `scene`'s time
// functions: the scene must outlive the problem.
template <int D>
VeryWeakSphProblemSettings<D> veryWeakSphProblemSettings(const Scene& scene, const GeometrySpec& geometry,
                                                         const VeryWeakSphSpec& spec, bool withBoundaries = true);

}  // namespace mfwave
