#pragma once
// Checkpoints in an output folder: written whole or not at all, the newest few kept, and the newest
// whole one found again on a restart (issue 20).
//
//   <folder>/checkpoint-<time loop, 4 digits>-<step, 12 digits>.mfwc
//
// A run numbers its time loops (a study's cases) in order (core/CheckpointStore); each keeps its
// own checkpoints.
// A file is written under a temporary name and renamed (core/AtomicFile), so a run killed while
// writing leaves the previous checkpoints intact; after the rename the older ones beyond `keep`
// are removed (keep 2: a checkpoint damaged later on disk still leaves one to go back to).

#include "io/checkpoint/Checkpoint.hpp"

#include <string>
#include <vector>

namespace mfwave {

// Writes `checkpoint` into `folder` and returns its path. Throws Error naming the file when it
// cannot be written whole.
std::string writeCheckpoint(const std::string& folder, const Checkpoint& checkpoint, int loop = 0, int keep = 2);

// The name (not the path) of time loop `loop`'s checkpoint at `step`: checkpoint-LLLL-SSSSSSSSSSSS.mfwc.
std::string checkpointFileName(int loop, long long step);

// Whether two paths name the same existing folder (false when either does not exist).
bool sameFolder(const std::string& a, const std::string& b);

// The checkpoint in the file at `path`. Throws CorruptCheckpoint when it is not whole, InputError
// ("--restart") when it is of another format version or cannot be read.
Checkpoint readCheckpointFile(const std::string& path);

// The checkpoint files of `folder` for time loop `loop` (all loops when negative), newest (highest
// loop, then highest step) first.
std::vector<std::string> checkpointFiles(const std::string& folder, int loop = -1);

struct RestartPoint {
  Checkpoint checkpoint;
  std::string path;
  std::vector<std::string> skipped;  // "<path>: <why>" for each newer file that was not whole
};

// The newest whole checkpoint of time loop `loop` in `folder`: damaged or truncated files are skipped, each named with
// its reason in `skipped`. Throws InputError("--restart", ...) when the folder holds none (naming
// what was skipped), and when the newest whole one belongs to another scene (its digest differs
// from `sceneDigest`) or another format version.
RestartPoint readNewestCheckpoint(const std::string& folder, const std::string& sceneDigest, int loop = 0);

}  // namespace mfwave
