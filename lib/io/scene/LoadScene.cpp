#include "io/scene/LoadScene.hpp"

#include "io/scene/KeyDepth.hpp"
#include "io/scene/Override.hpp"

#include <filesystem>
#include <fstream>
#include <iterator>

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
  std::error_code ec;
  if (!fs::is_regular_file(path, ec))
    throw SceneError("", "--scene", "cannot read the scene file '" + path + "': " +
                                        (fs::exists(path, ec) ? "not a regular file" : "no such file"));
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneError("", "--scene", "cannot read the scene file '" + path + "'");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw SceneError("", "--scene", "cannot read the scene file '" + path + "'");
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
