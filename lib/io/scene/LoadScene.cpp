#include "io/scene/LoadScene.hpp"

#include "core/BoundedRead.hpp"
#include "io/scene/KeyDepth.hpp"
#include "io/scene/Override.hpp"

#include <filesystem>

namespace mfwave {
namespace {

SceneReader finish(toml::table&& table, const std::string& sourceName, const std::vector<std::string>& overrides,
                   SceneSchema schema, const std::string& baseDirectory) {
  std::vector<std::string> overridden;
  for (const auto& assignment : overrides) overridden.push_back(applyOverride(table, assignment));
  SceneReader reader(std::move(table), sourceName, std::move(schema), baseDirectory);
  for (const auto& path : overridden) reader.markOverridden(path);
  return reader;
}

toml::table parseText(const std::string& text, const std::string& sourceName) {
  if (text.size() > kMaxSceneBytes)
    throw SceneError(sourceName, "(syntax)", "the scene text is larger than the limit of " +
                                                 std::to_string(kMaxSceneBytes) + " bytes");
  checkKeyDepth(text, sourceName);  // before toml++, which would overflow the stack on a deep key
  try {
    return toml::parse(text, std::string_view(sourceName));
  } catch (const toml::parse_error& e) {
    const auto& begin = e.source().begin;
    throw SceneError(sourceName + ":" + std::to_string(begin.line) + ":" + std::to_string(begin.column), "(syntax)",
                     std::string(e.description()));
  }
}

}  // namespace

SceneReader loadScene(const std::string& path, const std::vector<std::string>& overrides, SceneSchema schema) {
  namespace fs = std::filesystem;
  std::string text;
  try {
    text = readBoundedFile(path, kMaxSceneBytes, "--scene", "the scene file");
  } catch (const InputError& e) {
    throw SceneError("", "--scene", e.problem());
  }
  const fs::path parent = fs::path(path).parent_path();
  return finish(parseText(text, path), path, overrides, std::move(schema),
                parent.empty() ? std::string(".") : parent.string());
}

SceneReader parseScene(const std::string& text, const std::string& sourceName,
                       const std::vector<std::string>& overrides, SceneSchema schema,
                       const std::string& baseDirectory) {
  return finish(parseText(text, sourceName), sourceName, overrides, std::move(schema), baseDirectory);
}

}  // namespace mfwave
