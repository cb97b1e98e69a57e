#include "io/scene/Scene.hpp"

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

}  // namespace mfwave
