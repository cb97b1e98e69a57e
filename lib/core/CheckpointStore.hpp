#pragma once
// Where a run's checkpoints go and come from (issue 20). Process-wide, like the interruption flag:
// a driver installs one once its output folder is ready (io/run: --checkpoint-every, --restart,
// output.checkpoint_every, output.checkpoint_seconds) and every TimeLoop::run of the process uses
// it, so the many places that build a time loop (each study's case) need no extra argument. With
// none installed (the default, and every test that does not install one) nothing is written.
//
// Time loops are numbered in the order they run (a study's cases run in a fixed order for a given
// scene), so a restart finds each loop's own checkpoints: a case that had finished takes its final
// state and does not step again, the case that was stepping goes on from its newest checkpoint,
// later cases start afresh.

#include "core/StateArchive.hpp"
#include "core/Types.hpp"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace mfwave {

struct CheckpointPoint {
  long step = 0;
  Real time = 0;
  StateArchive archive;
  std::string source;  // the file it came from, for messages
};

class CheckpointStore {
 public:
  virtual ~CheckpointStore() = default;

  // 0: never by count / by wall clock. A loop always writes one when it ends or is interrupted.
  virtual long everySteps() const = 0;
  virtual double everySeconds() const = 0;
  // The key or option to name when a run cannot be checkpointed ("--checkpoint-every", ...).
  virtual std::string settingName() const = 0;
  // True when every rank of a split run writes its share of each checkpoint: then a wall-clock
  // period needs a loop that agrees its steps across the ranks (TimeLoop::agreeAcrossRanks).
  virtual bool sharedByRanks() const { return false; }

  // The number of the next time loop of this process (0, 1, ...).
  int claimLoop() { return loops_++; }
  // The newest whole checkpoint of loop `loop` when this run resumes one; nothing otherwise.
  virtual std::optional<CheckpointPoint> resumePoint(int loop) = 0;
  virtual void write(int loop, long step, Real time, const StateArchive& archive) = 0;

  // Where the checkpoints go (for the message an interrupted run ends with); empty if nowhere a
  // user could name.
  virtual std::string folder() const { return {}; }

  // What the run should say about its checkpoints (resumed from where, what was skipped).
  const std::vector<std::string>& notes() const { return notes_; }
  void addNote(std::string note) { notes_.push_back(std::move(note)); }

 private:
  int loops_ = 0;
  std::vector<std::string> notes_;
};

// The store of this process (nullptr: no checkpoints). Installing replaces the previous one.
void installCheckpointStore(std::shared_ptr<CheckpointStore> store);
CheckpointStore* checkpointStore();

}  // namespace mfwave
