#include "studies/lamb3d/LambReflection.hpp"

#include "io/scene/Format.hpp"
#include "particles/BoxFace.hpp"

#include <algorithm>
#include <iomanip>
#include <sstream>

namespace mfwave::lamb3d {

template <int D>
FirstReflection firstReflection(const Scene& scene, const ParticleSet<D>& particles, const std::vector<Probe>& probes,
                                unsigned faces) {
  const LoadSpec& load = scene.loads[0];
  const int normalAxis = faceAxis(load.face);
  const Real cp = scene.material.material().pWaveSpeed();
  const GeometrySpec& g = scene.geometry;
  FirstReflection first;
  for (const Probe& probe : probes) {
    const Vec<D> x = particles.position(probe.particle);
    for (int face = 0; face < 2 * D; ++face) {
      if ((faces & faceBit(face)) == 0) continue;
      const int axis = faceAxis(face);
      const auto a = static_cast<std::size_t>(axis);
      const Real wall = faceSign(face) < 0 ? g.lower[a] : g.upper[a];
      Vec<D> image = x;
      image[axis] = 2 * wall - x[axis];
      // the patch's nearest point to the image: the image clamped to the patch along each axis of its face
      Vec<D> source;
      for (int along = 0; along < D; ++along) {
        const auto b = static_cast<std::size_t>(along);
        source[along] = along == normalAxis ? load.centre[b]
                                            : std::clamp(image[along], load.centre[b] - load.halfWidth[b],
                                                         load.centre[b] + load.halfWidth[b]);
      }
      const Real time = (image - source).norm() / cp;
      if (time < first.time) {
        first.time = time;
        std::ostringstream path;
        path << std::setprecision(3) << (image - source).norm() << " / c_p from the load's patch via the "
             << (faceSign(face) < 0 ? "-" : "+") << axisName(axis) << " face to probe " << probe.name;
        first.path = path.str();
      }
    }
  }
  return first;
}

template FirstReflection firstReflection<2>(const Scene&, const ParticleSet<2>&, const std::vector<Probe>&, unsigned);
template FirstReflection firstReflection<3>(const Scene&, const ParticleSet<3>&, const std::vector<Probe>&, unsigned);

std::string reflectionNote(const std::string& caseName, const std::string& what, const FirstReflection& reflection,
                           Real errorWindow) {
  std::ostringstream note;
  note << std::setprecision(3) << caseName << ": " << what
       << ": the first P wave they reflect reaches a probe at t = " << reflection.time << " (" << reflection.path << ")"
       << (reflection.time > errorWindow
               ? ", after the error window " + scene::formatNumber(errorWindow) +
                     ", so the errors do not see the difference; later samples do"
               : ", INSIDE the error window " + scene::formatNumber(errorWindow) +
                     ": the errors include reflections the scene's faces would not make");
  return note.str();
}

}  // namespace mfwave::lamb3d
