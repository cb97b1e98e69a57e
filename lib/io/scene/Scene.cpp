#include "io/scene/Scene.hpp"

#include <algorithm>
#include <limits>

namespace mfwave {

Scene readScene(SceneReader& reader) {
  Scene scene;
  scene.info = readSceneInfo(reader);
  scene.geometry = readGeometry(reader, scene.info.dimension);
  scene.material = readMaterial(reader);
  scene.method = readMethod(reader);
  scene.boundaries = readBoundaries(reader, scene.geometry);
  scene.loads = readLoads(reader, scene.geometry);
  scene.integrator = readIntegrator(reader);
  scene.probes = readProbes(reader, scene.geometry);
  scene.output = readOutput(reader, scene.info.name, scene.info.dimension);
  scene.stability = readStability(reader);
  return scene;
}

Real loadsQuietAfter(const Scene& scene) {
  Real quiet = -std::numeric_limits<Real>::infinity();
  for (const LoadSpec& load : scene.loads) quiet = std::max(quiet, load.timeFunction.quietAfter());
  for (const BoundarySpec& b : scene.boundaries)
    if (b.type == BoundaryType::Traction || b.type == BoundaryType::Displacement)
      quiet = std::max(quiet, b.timeFunction.quietAfter());
  return quiet;
}

}  // namespace mfwave
