#pragma once
// When the first wave the box's other faces send back reaches a probe of the Lamb scene (2-D: the
// rectangle, 3-D: the block): the RK collocation case (fixed faces) and the updated-Lagrangian SPH
// case (free faces) stand in for the scene's transmitting faces with reflecting ones, and say from
// when their probes see it.

#include "io/scene/Scene.hpp"
#include "observers/ProbeRecorder.hpp"
#include "particles/ParticleSet.hpp"

#include <limits>
#include <string>
#include <vector>

namespace mfwave::lamb3d {

struct FirstReflection {
  Real time = std::numeric_limits<Real>::infinity();
  std::string path;  // "13.5 / c_p from the load's patch via the +x face to probe receiver"
};

// The earliest arrival at a probe of a P wave that leaves the load's patch (a segment of its face in
// 2-D, a rectangle in 3-D), reflects once off a face of `faces` (a BoxFace mask) of the case's `box`
// and reaches the probe: the distance from the patch to the probe's mirror image in that face, over
// c_p (the fastest wave, whatever the face's condition). The scene's first load is the surface_patch.
// For data/scenes/lamb3d.toml with fixed or free side faces: 4.5 / sqrt 3 = 2.60, from the square's
// edge x = 0.5 via the +x face (x = 3.5) to the receiver at x = 2, inside the error window 6.
template <int D>
FirstReflection firstReflection(const Scene& scene, const GeometrySpec& box, const ParticleSet<D>& particles,
                                const std::vector<Probe>& probes, unsigned faces);

// The case's note on the faces that stand in for the scene's: "<case>: <what>: the first P wave they
// reflect reaches a probe at t = <time> (<path>), after the error window <w>, so the errors do not
// see the difference; later samples do" (or that it arrives INSIDE the window, and what that means).
std::string reflectionNote(const std::string& caseName, const std::string& what, const FirstReflection& reflection,
                           Real errorWindow);

}  // namespace mfwave::lamb3d
