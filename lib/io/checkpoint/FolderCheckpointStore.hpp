#pragma once
// The checkpoint store a driver installs (core/CheckpointStore): checkpoints written into the output
// folder (io/checkpoint/CheckpointFolder, the newest two of each time loop kept), and on a restart
// read back from the folder given to --restart.

#include "core/CheckpointStore.hpp"
#include "io/checkpoint/Checkpoint.hpp"

#include <string>
#include <vector>

namespace mfwave {

struct CheckpointSettings {
  long everySteps = 0;       // 0: not by count
  double everySeconds = 0;   // 0: not by wall clock
  std::string setting = "--checkpoint-every";  // what to name when the run cannot be checkpointed
  std::string restartFolder;  // --restart: where to resume from (empty: a fresh run)
};

// The checkpoint of a run's state: `archive` at (step, time) of the scene with `sceneDigest`, the
// resolved scene beside it as the text array "scene" when given, so that a checkpoint says by itself
// what it is a state of. What every store writes (this one, and each rank's of a run on ranks).
Checkpoint stateCheckpoint(const std::string& sceneDigest, long step, Real time, const StateArchive& archive,
                           const std::string& sceneText);

class FolderCheckpointStore : public CheckpointStore {
 public:
  // On a fresh run, removes the checkpoints a previous run left in `outputFolder` (they would be
  // taken for this run's). On a restart, checks at once that `settings.restartFolder` holds a
  // whole checkpoint of this scene (InputError "--restart" otherwise: none, all damaged, another
  // scene's or another format version's), naming every file it skipped.
  // `sceneText` (the resolved scene) goes into every checkpoint as the array "scene", so a
  // checkpoint says by itself what it is a state of.
  FolderCheckpointStore(std::string outputFolder, std::string sceneDigest, CheckpointSettings settings,
                        std::string sceneText = {});

  long everySteps() const override { return settings_.everySteps; }
  double everySeconds() const override { return settings_.everySeconds; }
  std::string settingName() const override { return settings_.setting; }
  std::optional<CheckpointPoint> resumePoint(int loop) override;
  void write(int loop, long step, Real time, const StateArchive& archive) override;
  std::string folder() const override { return folder_; }

 private:
  // Says each damaged file skipped (on stderr and in the notes), once however often it is met.
  void noteSkipped(const std::vector<std::string>& skipped);

  std::string folder_;
  std::string digest_;
  CheckpointSettings settings_;
  std::string sceneText_;
};

}  // namespace mfwave
