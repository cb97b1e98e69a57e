#include "io/run/SceneDriver.hpp"

#include "core/AtomicFile.hpp"
#include "io/scene/LoadScene.hpp"

#include <filesystem>

namespace mfwave {

SceneReader loadDriverScene(const DriverOptions& options, const SceneSchema& schema) {
  if (options.scenePath.empty()) return parseScene("", "(defaults)", options.overrides, schema);
  return loadScene(options.scenePath, options.overrides, schema);
}

std::string prepareOutputFolder(const DriverOptions& options, const std::string& sceneFolder,
                                const SceneReader& reader) {
  const std::string folder = options.outputFolder.empty() ? sceneFolder : options.outputFolder;
  std::filesystem::create_directories(folder);
  AtomicFile file(folder + "/scene.resolved.toml");
  file.stream() << reader.resolvedToml();
  file.commit();
  return folder;
}

}  // namespace mfwave
