#include "io/run/SceneDriver.hpp"

#include "io/run/RunDriver.hpp"

#include "core/AtomicFile.hpp"
#include "core/Error.hpp"
#include "io/checkpoint/FolderCheckpointStore.hpp"
#include "io/scene/LoadScene.hpp"

#include <cstdint>
#include <filesystem>
#include <memory>

namespace mfwave {

namespace {

// Keys that change where and how often a run is saved, not what it computes: a checkpoint taken
// with one value goes on with another.
const std::vector<std::string> kNotPartOfTheComputation = {"output.folder", "output.checkpoint_every",
                                                           "output.checkpoint_seconds"};

void installCheckpoints(const DriverOptions& options, const std::string& folder, const SceneReader& reader,
                        const CheckpointStoreMaker& makeStore) {
  CheckpointSettings settings;
  const auto sceneValue = [&](const char* path) { return reader.root().at_path(path).value_or(0.0); };
  settings.everySteps = static_cast<long>(reader.root().at_path("output.checkpoint_every").value_or(std::int64_t{0}));
  settings.everySeconds = sceneValue("output.checkpoint_seconds");
  settings.setting = settings.everySeconds > 0 ? "output.checkpoint_seconds" : "output.checkpoint_every";
  if (options.checkpointSteps > 0 || options.checkpointSeconds > 0) {
    settings.everySteps = options.checkpointSteps;
    settings.everySeconds = options.checkpointSeconds;
    settings.setting = "--checkpoint-every";
  }
  settings.restartFolder = options.restartFolder;
  if (settings.everySteps <= 0 && settings.everySeconds <= 0 && settings.restartFolder.empty()) {
    installCheckpointStore(nullptr);
    return;
  }
  if (!settings.restartFolder.empty() && settings.everySteps <= 0 && settings.everySeconds <= 0)
    settings.setting = "--restart";
  const std::string digest = reader.digest(kNotPartOfTheComputation);
  const std::string sceneText = reader.canonicalToml(kNotPartOfTheComputation);
  installCheckpointStore(makeStore ? makeStore(folder, digest, settings, sceneText)
                                   : std::make_shared<FolderCheckpointStore>(folder, digest, settings, sceneText));
}

}  // namespace

SceneReader loadDriverScene(const DriverOptions& options, const SceneSchema& schema) {
  if (options.scenePath.empty() && !options.restartFolder.empty()) {
    // The interrupted run's own scene, every override and default written out.
    const std::string resolved = (std::filesystem::path(options.restartFolder) / "scene.resolved.toml").string();
    if (!std::filesystem::is_regular_file(resolved))
      throw InputError("--restart", "'" + options.restartFolder +
                                        "' has no scene.resolved.toml: give the scene with --scene");
    return loadScene(resolved, options.overrides, schema);
  }
  if (options.scenePath.empty()) return parseScene("", "(defaults)", options.overrides, schema);
  return loadScene(options.scenePath, options.overrides, schema);
}

std::string prepareOutputFolder(const DriverOptions& options, const std::string& sceneFolder,
                                const SceneReader& reader, const CheckpointStoreMaker& makeStore) {
  if (options.checkOnly) throw CheckCompleted{};
  // A restart writes into the folder it goes on from, unless told otherwise.
  const std::string folder = !options.outputFolder.empty()  ? options.outputFolder
                             : !options.restartFolder.empty() ? options.restartFolder
                                                              : sceneFolder;
  // A folder that cannot be made or written is an error of the environment (exit 1, as a full disk
  // later is), said before any work with the path and the option or key it came from.
  const std::string key = !options.outputFolder.empty()    ? "--out"
                          : !options.restartFolder.empty() ? "--restart"
                                                           : "output.folder";
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error || !std::filesystem::is_directory(folder))
    throw Error(key + ": cannot make the output folder '" + folder + "': " +
                (error ? error.message() : std::string("it exists and is not a folder")));
  // Before the resolved scene is written: a restart refused (another scene's checkpoints) leaves the
  // folder as it was.
  installCheckpoints(options, folder, reader, makeStore);
  // A restart that read its scene from this folder's scene.resolved.toml leaves it as it is (the
  // same scene; only its header, the source's name, would change).
  std::error_code same;
  if (options.scenePath.empty() && !options.restartFolder.empty() &&
      std::filesystem::equivalent(options.restartFolder, folder, same) && options.overrides.empty())
    return folder;
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
