#include "io/scene/OutputSpec.hpp"

#include "io/scene/Faces.hpp"
#include "io/scene/Format.hpp"

#include <algorithm>

namespace mfwave {

OutputSpec readOutput(SceneReader& reader, const std::string& sceneName, int dimension) {
  OutputSpec o;
  o.folder = reader.string("output.folder", "out/" + sceneName);
  if (o.folder.empty()) reader.fail("output.folder", "must not be empty");
  o.every = static_cast<long>(reader.integer("output.every"));
  o.vtk = reader.boolean("output.vtk");
  o.png = reader.boolean("output.png");
  o.pngField = reader.string("output.png_field");
  o.pngComponent = reader.string("output.png_component");
  auto components = componentNames(dimension);
  components.push_back("magnitude");
  if (std::find(components.begin(), components.end(), o.pngComponent) == components.end())
    reader.fail("output.png_component", "'" + o.pngComponent + "' is not a component of a " +
                                            std::to_string(dimension) + "-D scene; valid: " + scene::joinNames(components));
  const auto named = std::find(components.begin(), components.end(), o.pngComponent) - components.begin();
  o.pngComponentIndex = o.pngComponent == "magnitude" ? -1 : static_cast<int>(named);
  o.pngPointSize = reader.number("output.png_point_size");
  o.pngWidth = static_cast<int>(reader.integer("output.png_width"));
  o.pngHeight = static_cast<int>(reader.integer("output.png_height"));
  o.probeEvery = static_cast<long>(reader.integer("output.probe_every"));
  o.energy = reader.boolean("output.energy");
  o.checkpointEvery = static_cast<long>(reader.integer("output.checkpoint_every"));
  o.checkpointSeconds = reader.number("output.checkpoint_seconds");
  return o;
}

}  // namespace mfwave
