#pragma once
// The common sections of a scene file as typed configuration. A driver:
//
//   SceneSchema schema = SceneSchema::common();            // + its own keys: schema.add("study.cases", ...)
//   SceneReader reader = loadScene(path, overrides, schema);
//   Scene scene = readScene(reader);                        // validates the common sections
//   ... the method reads its [method] options, the driver its own keys ...
//   reader.checkAllKeysRead();                              // unknown keys, before any work
//   write(scene.output.folder + "/scene.resolved.toml", reader.resolvedToml());
//   ParticleSet<3> particles = buildParticles<3>(scene.geometry);

#include "io/scene/BoundarySpec.hpp"
#include "io/scene/GeometrySpec.hpp"
#include "io/scene/IntegratorSpec.hpp"
#include "io/scene/LoadSpec.hpp"
#include "io/scene/MaterialSpec.hpp"
#include "io/scene/MethodSpec.hpp"
#include "io/scene/OutputSpec.hpp"
#include "io/scene/ProbeSpec.hpp"
#include "io/scene/SceneInfo.hpp"
#include "io/scene/SceneReader.hpp"
#include "io/scene/StabilitySpec.hpp"

#include <vector>

namespace mfwave {

struct Scene {
  SceneInfo info;
  GeometrySpec geometry;
  MaterialSpec material;
  MethodSpec method;
  std::vector<BoundarySpec> boundaries;
  std::vector<LoadSpec> loads;
  IntegratorSpec integrator;
  std::vector<ProbeSpec> probes;
  OutputSpec output;
  StabilitySpec stability;
};

// Reads and validates every common section, in the order above (later sections depend on the
// dimension and the geometry). Throws SceneError at the first problem.
Scene readScene(SceneReader& reader);

// The time after which no load, traction face or prescribed displacement acts any more
// (TimeFunction::quietAfter); -infinity for a scene without any.
Real loadsQuietAfter(const Scene& scene);

}  // namespace mfwave
