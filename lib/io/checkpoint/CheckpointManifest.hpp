#pragma once
// The one manifest of a run checkpointed on several MPI ranks (issue 22). Each rank writes its own
// checkpoints (io/checkpoint/CheckpointFolder) into its own folder; rank 0 writes this manifest
// after every rank has completed a checkpoint, so it names one that is whole on every rank:
//
//   <folder>/rank-<r>-of-<R>/checkpoint-<loop>-<step>.mfwc   each rank's state (its owned dofs)
//   <folder>/checkpoint-manifest.txt                          written by rank 0, atomically
//
// The manifest is text, one "key value" a line:
//   mfwave-checkpoint-manifest 1 | ranks R | scene_digest D (the rest of the line) | loop L | step S | time T (17 digits) |
//   loop_ranks all (every rank stepped the loop) or 0 (rank 0 alone) | file <relative path> per file
// No MPI here: the ranks' agreement is decomposition/mpi/RankCheckpointStore's; this is the format.

#include "core/Types.hpp"

#include <optional>
#include <string>
#include <vector>

namespace mfwave {

inline constexpr const char* kCheckpointManifestName = "checkpoint-manifest.txt";

struct CheckpointManifest {
  int ranks = 1;
  std::string sceneDigest;
  int loop = 0;
  long long step = 0;
  Real time = 0;
  bool rankZeroAlone = false;       // the loop ran on rank 0 alone (a case that could not be distributed)
  std::vector<std::string> files;   // relative to the manifest's folder
};

// "rank-<rank>-of-<ranks>": the folder, under the output folder, of one rank's checkpoints.
std::string rankCheckpointFolderName(int rank, int ranks);

// Writes <folder>/checkpoint-manifest.txt under a temporary name, then renames it (core/AtomicFile).
void writeCheckpointManifest(const std::string& folder, const CheckpointManifest& manifest);

// The manifest of `folder`, nothing when it has none. Throws InputError("--restart", ...) naming the
// file and line when it is not a manifest this build can read.
std::optional<CheckpointManifest> readCheckpointManifest(const std::string& folder);

}  // namespace mfwave
