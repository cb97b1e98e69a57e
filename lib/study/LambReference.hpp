#pragma once
// The exact reference of a Lamb scene (Ding et al. section 8): when a scene is the half-space
// problem LambSquareLoad solves (one square surface patch of normal traction on a Poisson solid,
// a piecewise-linear load history from 0), that solution for the scene's load, and where a probe
// sees it (the normal component on the loaded face). Nothing here depends on the method: every
// method that runs a Lamb scene scores its probes through these functions.

#include "analytic/LambSquareLoad.hpp"
#include "io/scene/Scene.hpp"
#include "kernels/Kernel.hpp"
#include "observers/ProbeRecorder.hpp"
#include "particles/ParticleSet.hpp"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace mfwave {

// Why the scene has no exact reference ("" when it has one).
std::string lambReferenceUnavailable(const Scene& scene);

// The exact response to the scene's load; the scene must have one (lambReferenceUnavailable empty).
LambSquareLoad lambReference(const Scene& scene);

// Where the reference applies to `probe`: its position relative to the load centre in the loaded
// face's plane (the two in-plane axes in cyclic order after the normal), when the probe reads the
// normal component of a particle on the loaded face; nothing otherwise.
std::optional<std::array<Real, 2>> lambSurfaceOffset(const Scene& scene, const ParticleSet<3>& particles,
                                                     const Probe& probe);

// The exact velocity (or displacement) at a surface offset at each of `times`.
std::vector<Real> lambExactSeries(const LambSquareLoad& exact, const std::array<Real, 2>& offset,
                                  const std::vector<Real>& times, bool velocity);

// The exact response to the load spread over the surface by the kernel: the square's response
// averaged over in-plane shifts z with the kernel's plane density int W(z, s) ds (normalised). A
// method whose surface tractions act through W cannot resolve the load more sharply than this, so
// its distance from the exact response is the part of an error the kernel's width alone explains.
std::vector<Real> kernelSmoothedLambSeries(const LambSquareLoad& exact, const Kernel& kernel,
                                           const std::array<Real, 2>& offset, const std::vector<Real>& times,
                                           bool velocity);

}  // namespace mfwave
