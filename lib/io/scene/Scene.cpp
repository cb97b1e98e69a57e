#include "io/scene/Scene.hpp"

#include "io/scene/ScenePath.hpp"

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
  // A symmetry plane is the solid's mirror, not a surface: nothing loads it.
  const std::uint8_t symmetry = facesWith(scene.boundaries, BoundaryType::Symmetry);
  for (std::size_t i = 0; i < scene.loads.size(); ++i)
    if (scene.loads[i].type == LoadType::SurfacePatch && (symmetry & (1u << scene.loads[i].face)) != 0)
      reader.fail(scene::childPath(scene::indexPath("load", i), "face"),
                  "is a symmetry plane (a mirror inside the solid); a patch on it loads nothing");
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
