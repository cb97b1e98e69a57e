#include "catalogue/CatalogueScene.hpp"

#include "catalogue/MethodCatalogue.hpp"
#include "catalogue/SceneSupport.hpp"
#include "io/scene/Format.hpp"
#include "io/scene/LoadScene.hpp"
#include "io/scene/SceneError.hpp"

#include <toml++/toml.h>

namespace mfwave {

std::optional<CatalogueScene> readCatalogueScene(const std::string& path, const std::vector<std::string>& overrides) {
  const SceneReader first = loadScene(path, overrides);
  if (!first.root().contains("scene")) return std::nullopt;
  const std::optional<std::string> name = first.root().at_path("method.name").value<std::string>();
  if (!name) throw first.error("method.name", "is required: one of the catalogue's methods (mfwave methods)");
  const MethodEntry* entry = findMethod(*name);
  if (!entry) {
    try {
      methodNamed(*name);
    } catch (const InputError& e) {
      throw first.error("method.name", scene::problemOf(e));
    }
  }
  SceneReader reader = loadScene(path, overrides, catalogueSchema(*entry));
  CatalogueScene out;
  out.scene = readScene(reader);
  out.choice = readMethodChoice(reader, *entry, out.scene.geometry.dimension);
  const std::vector<UnsupportedFeature> problems = unsupportedFeatures(out.scene, *entry);
  if (!problems.empty()) throw reader.error(problems.front().key, problems.front().message());
  return out;
}

}  // namespace mfwave
