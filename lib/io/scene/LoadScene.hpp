#pragma once
// Reads a scene file (or text), applies the --set overrides and returns the reader.
// A file that cannot be read -> SceneError key "--scene"; a TOML syntax error -> SceneError key
// "(syntax)" located at file:line:column; a malformed override -> key "--set".

#include "io/scene/SceneReader.hpp"

#include <string>
#include <vector>

namespace mfwave {

SceneReader loadScene(const std::string& path, const std::vector<std::string>& overrides = {},
                      SceneSchema schema = SceneSchema::common());

// The same for scene text held in memory; `sourceName` labels messages, relative file paths
// are resolved against `baseDirectory`.
SceneReader parseScene(const std::string& text, const std::string& sourceName,
                       const std::vector<std::string>& overrides = {}, SceneSchema schema = SceneSchema::common(),
                       const std::string& baseDirectory = ".");

}  // namespace mfwave
