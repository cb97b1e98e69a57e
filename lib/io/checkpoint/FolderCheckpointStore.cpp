#include "io/checkpoint/FolderCheckpointStore.hpp"

#include "io/checkpoint/CheckpointFolder.hpp"
#include "io/checkpoint/CheckpointManifest.hpp"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <sstream>

namespace mfwave {
namespace {

namespace fs = std::filesystem;

std::string describe(const CheckpointPoint& point) {
  std::ostringstream text;
  text << point.source << " (step " << point.step << ", t = " << point.time << ")";
  return text.str();
}

}  // namespace

FolderCheckpointStore::FolderCheckpointStore(std::string outputFolder, std::string sceneDigest,
                                             CheckpointSettings settings, std::string sceneText)
    : folder_(std::move(outputFolder)),
      digest_(std::move(sceneDigest)),
      settings_(std::move(settings)),
      sceneText_(std::move(sceneText)) {
  if (!settings_.restartFolder.empty()) {
    // Checkpoints written per rank (decomposition/mpi/RankCheckpointStore) hold each rank's share of
    // the state: a serial run cannot go on from them.
    if (const auto manifest = readCheckpointManifest(settings_.restartFolder))
      throw InputError("--restart", "'" + settings_.restartFolder + "' holds the checkpoints of a run on " +
                                        std::to_string(manifest->ranks) +
                                        " MPI ranks; this run is serial (1 rank): each rank's checkpoint holds its "
                                        "share of the state, and restarting on another rank count would need a "
                                        "redistribution, which is not done: restart under mpirun -np " +
                                        std::to_string(manifest->ranks));
    noteSkipped(readNewestCheckpoint(settings_.restartFolder, digest_, -1).skipped);
  }
  if (settings_.restartFolder.empty() || !sameFolder(settings_.restartFolder, folder_)) {
    std::error_code ec;
    for (const std::string& stale : checkpointFiles(folder_)) fs::remove(stale, ec);
    // A manifest a run on ranks left would make a later restart look for their checkpoints.
    fs::remove(fs::path(folder_) / kCheckpointManifestName, ec);
  }
}

std::optional<CheckpointPoint> FolderCheckpointStore::resumePoint(int loop) {
  if (settings_.restartFolder.empty() || checkpointFiles(settings_.restartFolder, loop).empty()) return std::nullopt;
  RestartPoint found;
  try {
    found = readNewestCheckpoint(settings_.restartFolder, digest_, loop);
  } catch (const InputError& e) {
    // Only damaged files of this loop (a whole one of another scene or format version was refused
    // when the store was made): the loop starts again from its beginning.
    addNote("time loop " + std::to_string(loop) + " starts again from its beginning: " + e.what());
    std::cerr << "checkpoint: " << notes().back() << "\n";
    return std::nullopt;
  }
  noteSkipped(found.skipped);
  CheckpointPoint point;
  point.step = found.checkpoint.step;
  point.time = found.checkpoint.time;
  point.archive = StateArchive(std::move(found.checkpoint.arrays));
  point.source = found.path;
  addNote("time loop " + std::to_string(loop) + " resumed from " + describe(point));
  return point;
}

void FolderCheckpointStore::noteSkipped(const std::vector<std::string>& skipped) {
  for (const std::string& file : skipped) {
    const std::string note = "checkpoint skipped: " + file;
    if (std::find(notes().begin(), notes().end(), note) != notes().end()) continue;  // said once
    std::cerr << note << "\n";
    addNote(note);
  }
}

Checkpoint stateCheckpoint(const std::string& sceneDigest, long step, Real time, const StateArchive& archive,
                           const std::string& sceneText) {
  Checkpoint checkpoint;
  checkpoint.sceneDigest = sceneDigest;
  checkpoint.step = step;
  checkpoint.time = time;
  StateArchive withScene(archive.arrays());
  if (!sceneText.empty()) withScene.putText("scene", sceneText);
  checkpoint.arrays = withScene.arrays();
  return checkpoint;
}

void FolderCheckpointStore::write(int loop, long step, Real time, const StateArchive& archive) {
  writeCheckpoint(folder_, stateCheckpoint(digest_, step, time, archive, sceneText_), loop);
}

}  // namespace mfwave
