#pragma once
// The start every scene-driven program shares, in the order a driver calls it:
//   SceneReader reader = loadDriverScene(cli.options(), schema);   // scene + --set overrides
//   ... read the scene and the driver's own keys; reader.checkAllKeysRead() ...
//   const std::string folder = prepareOutputFolder(cli.options(), sceneFolder, reader);
// so every driver and tool resolves its scene and output folder alike.

#include "io/checkpoint/FolderCheckpointStore.hpp"
#include "io/run/DriverCommandLine.hpp"
#include "io/scene/SceneReader.hpp"

#include <functional>
#include <memory>
#include <string>

namespace mfwave {

// The scene named by --scene, or on --restart without --scene the restarted folder's
// scene.resolved.toml, with the --set overrides applied; for a tool whose scene is optional (no
// --scene given), the schema's defaults with the overrides.
SceneReader loadDriverScene(const DriverOptions& options, const SceneSchema& schema);

//
// prepareOutputFolder: --out when given, else the --restart folder, else `sceneFolder` (the scene's
// output.folder); created if missing, and the resolved scene (every key with the value used)
// written into it as scene.resolved.toml, so the run can be repeated exactly. Returns the folder.
// It also installs the process's checkpoint store (core/CheckpointStore) when the run writes
// checkpoints (--checkpoint-every, output.checkpoint_every, output.checkpoint_seconds) or goes on
// from one (--restart: refused with exit 2 when the folder holds no whole checkpoint of this scene).
// The store is a FolderCheckpointStore unless `makeStore` is given: a driver under mpirun passes
// one that writes per rank (decomposition/mpi/RankCheckpointStore), so that io links no MPI.
// With --check (options.checkOnly) it stops the program instead, before making anything: every
// driver calls it once its scene and plan are read and checkAllKeysRead has passed, so reaching it
// means the scene is valid. It throws CheckCompleted, which runDriver turns into exit 0.
using CheckpointStoreMaker = std::function<std::shared_ptr<CheckpointStore>(
    const std::string& folder, const std::string& sceneDigest, const CheckpointSettings& settings,
    const std::string& sceneText)>;
std::string prepareOutputFolder(const DriverOptions& options, const std::string& sceneFolder,
                                const SceneReader& reader, const CheckpointStoreMaker& makeStore = {});

}  // namespace mfwave
