#pragma once
// Checkpoints of a run on several MPI ranks (issue 22): each rank writes its own archive (the state
// it owns) into its own folder, and rank 0 writes one manifest naming the newest checkpoint every
// rank completed (io/checkpoint/CheckpointManifest: the layout on disk).
//
// The ranks agree on every checkpoint:
//  - when: by step count only (deterministic). A wall-clock period (--checkpoint-every Ns,
//    output.checkpoint_seconds) is refused with an InputError naming the setting: each rank's clock
//    would fire at another step.
//  - what is whole: after writing, the ranks reduce (MPI_Allreduce) before rank 0 names the step in
//    the manifest, so the manifest never names a step some rank has not finished writing.
//  - where to go on from (--restart): the newest step whose checkpoint is whole on every rank
//    (reduced over the ranks; each keeps its newest two), so a run killed while one rank was a
//    checkpoint ahead goes on from the one before; with none in common the loop starts again.
// A restart on another rank count is refused (InputError "--restart" naming both counts): a rank's
// state is its block of the decomposition, and another count would need a redistribution.
//
// A time loop that runs on rank 0 alone (a case that cannot be distributed) is marked by a
// RankZeroAloneLoop on every rank around it: rank 0 writes and reads its checkpoints without
// waiting for the others, and the other ranks skip its loop number so the numbering stays the same
// on every rank.

#include "io/checkpoint/FolderCheckpointStore.hpp"

#include <mpi.h>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace mfwave {

class RankCheckpointStore : public CheckpointStore {
 public:
  // Collective over `comm`. On a fresh run removes the checkpoints a previous run left in
  // `outputFolder` (this rank's folder; rank 0 also the manifest and other rank counts' folders). On
  // a restart checks at once that settings.restartFolder has a manifest of this scene written by as
  // many ranks as `comm` has (InputError "--restart" otherwise).
  RankCheckpointStore(std::string outputFolder, std::string sceneDigest, CheckpointSettings settings,
                      std::string sceneText, MPI_Comm comm);

  long everySteps() const override { return settings_.everySteps; }
  double everySeconds() const override { return settings_.everySeconds; }
  // While a loop runs on rank 0 alone its checkpoints are rank 0's alone.
  bool sharedByRanks() const override { return !alone_ && ranks_ > 1; }
  std::string settingName() const override { return settings_.setting; }
  std::optional<CheckpointPoint> resumePoint(int loop) override;
  void write(int loop, long step, Real time, const StateArchive& archive) override;
  std::string folder() const override { return folder_; }

  int rank() const { return rank_; }
  // Set on rank 0 while a loop runs there alone (RankZeroAloneLoop).
  void setRankZeroAlone(bool alone) { alone_ = alone; }

 private:
  struct WholeFile {
    long long step;
    std::string path;
  };
  // This rank's whole checkpoints of `loop` in the restart folder, newest first (damaged ones noted).
  std::vector<WholeFile> wholeFiles(int loop);
  // The newest step whose checkpoint every rank holds whole, -1 if none (collective).
  long long commonStep(const std::vector<WholeFile>& whole) const;
  void note(const std::string& text, bool alsoOnStderr);

  std::string folder_;      // the output folder (the manifest's)
  std::string rankFolder_;  // <folder>/rank-<r>-of-<R>
  std::string digest_;
  CheckpointSettings settings_;
  std::string sceneText_;
  MPI_Comm comm_;
  int rank_ = 0, ranks_ = 1;
  bool alone_ = false;
};

// Makes a RankCheckpointStore on MPI_COMM_WORLD: the maker io/run/SceneDriver's prepareOutputFolder
// takes (a driver passes it when MpiSession::size() > 1).
std::shared_ptr<CheckpointStore> makeRankCheckpointStore(const std::string& folder, const std::string& sceneDigest,
                                                         const CheckpointSettings& settings,
                                                         const std::string& sceneText);

// What a driver passes prepareOutputFolder as its store maker: makeRankCheckpointStore when this
// process is one of several MPI ranks, empty (the serial folder store) otherwise.
using RankAwareStoreMaker = std::function<std::shared_ptr<CheckpointStore>(
    const std::string&, const std::string&, const CheckpointSettings&, const std::string&)>;
RankAwareStoreMaker rankAwareCheckpointStoreMaker();

// Around a time loop that runs on rank 0 alone, on every rank (constructed before the loop, on the
// ranks that skip it too). Does nothing unless a RankCheckpointStore is installed.
class RankZeroAloneLoop {
 public:
  RankZeroAloneLoop();
  ~RankZeroAloneLoop();
  RankZeroAloneLoop(const RankZeroAloneLoop&) = delete;
  RankZeroAloneLoop& operator=(const RankZeroAloneLoop&) = delete;

 private:
  RankCheckpointStore* store_ = nullptr;
};

}  // namespace mfwave
