#include "io/scene/SceneInfo.hpp"

namespace mfwave {

SceneInfo readSceneInfo(SceneReader& reader) {
  reader.table("scene", true);
  SceneInfo info;
  info.name = reader.string("scene.name");
  if (info.name.find_first_not_of(" \t") == std::string::npos) reader.fail("scene.name", "must not be empty");
  info.description = reader.optionalString("scene.description").value_or("");
  info.dimension = static_cast<int>(reader.integer("scene.dimension"));
  return info;
}

}  // namespace mfwave
