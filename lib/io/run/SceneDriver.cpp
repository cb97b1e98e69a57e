#include "io/run/SceneDriver.hpp"

#include "core/AtomicFile.hpp"
#include "core/Error.hpp"
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
  // A folder that cannot be made or written is an error of the environment (exit 1, as a full disk
  // later is), said before any work with the path and the option or key it came from.
  const std::string key = options.outputFolder.empty() ? "output.folder" : "--out";
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error || !std::filesystem::is_directory(folder))
    throw Error(key + ": cannot make the output folder '" + folder + "': " +
                (error ? error.message() : std::string("it exists and is not a folder")));
  try {
    AtomicFile file(folder + "/scene.resolved.toml");
    file.stream() << reader.resolvedToml();
    file.commit();
  } catch (const Error& e) {
    throw Error(key + ": cannot write in the output folder '" + folder + "': " + e.what());
  }
  return folder;
}

}  // namespace mfwave
