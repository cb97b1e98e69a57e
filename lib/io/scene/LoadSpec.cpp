#include "io/scene/LoadSpec.hpp"

#include "io/scene/Format.hpp"
#include "io/scene/ScenePath.hpp"
#include "io/scene/TimeFunctionSpec.hpp"

#include <cmath>

namespace mfwave {

std::string loadTypeName(LoadType type) { return type == LoadType::PointForce ? "point_force" : "body_force"; }

std::vector<LoadSpec> readLoads(SceneReader& reader, const GeometrySpec& geometry) {
  const auto d = static_cast<std::size_t>(geometry.dimension);
  std::vector<LoadSpec> loads;
  const std::size_t count = reader.count("load");
  for (std::size_t i = 0; i < count; ++i) {
    const std::string entry = scene::indexPath("load", i);
    const auto key = [&](const char* name) { return scene::childPath(entry, name); };
    LoadSpec load;
    load.type = reader.string(key("type")) == "point_force" ? LoadType::PointForce : LoadType::BodyForce;
    if (load.type == LoadType::PointForce) {
      load.position = reader.numbers(key("position"), d);
      if (!geometry.contains(load.position))
        reader.fail(key("position"), scene::formatPoint(load.position) + " lies outside the geometry box " +
                                         geometry.describeBox());
      load.direction = reader.numbers(key("direction"), d);
      Real norm = 0;
      for (const Real c : load.direction) norm += c * c;
      norm = std::sqrt(norm);
      if (!(norm > 0)) reader.fail(key("direction"), "must not be the zero vector");
      for (Real& c : load.direction) c /= norm;
      load.amplitude = reader.number(key("amplitude"));
      load.timeFunction = readTimeFunction(reader, key("time_function"), true);
    } else {
      load.value = reader.numbers(key("value"), d);
      load.timeFunction = readTimeFunction(reader, key("time_function"), false);
    }
    loads.push_back(std::move(load));
  }
  return loads;
}

}  // namespace mfwave
