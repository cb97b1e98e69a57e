#include "decomposition/mpi/RankCheckpointStore.hpp"

#include "decomposition/mpi/MpiSession.hpp"

#include "core/Error.hpp"
#include "io/checkpoint/CheckpointFolder.hpp"
#include "io/checkpoint/CheckpointManifest.hpp"

#include <algorithm>
#include <climits>
#include <filesystem>
#include <iostream>
#include <sstream>

namespace mfwave {
namespace {

namespace fs = std::filesystem;

void removeCheckpointFiles(const std::string& folder) {
  std::error_code ec;
  for (const std::string& stale : checkpointFiles(folder)) fs::remove(stale, ec);
}

long long reduce(long long value, MPI_Op op, MPI_Comm comm) {
  long long out = 0;
  MPI_Allreduce(&value, &out, 1, MPI_LONG_LONG, op, comm);
  return out;
}

}  // namespace

RankCheckpointStore::RankCheckpointStore(std::string outputFolder, std::string sceneDigest,
                                         CheckpointSettings settings, std::string sceneText, MPI_Comm comm)
    : folder_(std::move(outputFolder)),
      digest_(std::move(sceneDigest)),
      settings_(std::move(settings)),
      sceneText_(std::move(sceneText)),
      comm_(comm) {
  MPI_Comm_rank(comm_, &rank_);
  MPI_Comm_size(comm_, &ranks_);
  const std::string counts = std::to_string(ranks_) + " MPI ranks";
  // A wall-clock period is taken: each rank's clock fires at another step, so the ranks' loops
  // agree at every step boundary whether one is due (TimeLoop::agreeAcrossRanks).
  rankFolder_ = (fs::path(folder_) / rankCheckpointFolderName(rank_, ranks_)).string();
  std::error_code ec;
  fs::create_directories(rankFolder_, ec);
  if (ec || !fs::is_directory(rankFolder_))
    throw Error("cannot make the checkpoint folder '" + rankFolder_ + "': " +
                (ec ? ec.message() : std::string("it exists and is not a folder")));

  const std::string& from = settings_.restartFolder;
  if (!from.empty()) {
    const std::optional<CheckpointManifest> manifest = readCheckpointManifest(from);
    if (!manifest && !checkpointFiles(from).empty())
      throw InputError("--restart", "'" + from + "' holds the checkpoints of a serial run (no " +
                                        kCheckpointManifestName + "); this run has " + counts +
                                        ": restarting on another rank count would need a redistribution of the "
                                        "state, which is not done; restart it without mpirun");
    if (!manifest)
      throw InputError("--restart", "'" + from + "' has no " + kCheckpointManifestName +
                                        ": no run on MPI ranks wrote checkpoints there");
    if (manifest->ranks != ranks_)
      throw InputError("--restart", "'" + from + "' holds checkpoints written by " + std::to_string(manifest->ranks) +
                                        " MPI ranks; this run has " + counts +
                                        ": each rank's checkpoint holds its block of the decomposition, and "
                                        "restarting on another rank count would need a redistribution of the "
                                        "state, which is not done; restart with mpirun -np " +
                                        std::to_string(manifest->ranks));
    if (manifest->sceneDigest != digest_)
      throw InputError("--restart", "the checkpoints in '" + from + "' belong to another scene (digest " +
                                        manifest->sceneDigest + ", this scene's " + digest_ + ")");
  }
  if (from.empty() || !sameFolder(from, folder_)) {
    // A previous run's checkpoints would be taken for this run's.
    removeCheckpointFiles(rankFolder_);
    if (rank_ == 0) {
      fs::remove(fs::path(folder_) / kCheckpointManifestName, ec);
      removeCheckpointFiles(folder_);  // a serial run's
      const std::string ours = rankCheckpointFolderName(0, ranks_);
      const std::string suffix = ours.substr(ours.find("-of-"));
      for (fs::directory_iterator it(folder_, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        const bool otherCount = name.rfind("rank-", 0) == 0 && name.find("-of-") != std::string::npos &&
                                name.compare(name.size() - std::min(name.size(), suffix.size()), suffix.size(),
                                             suffix) != 0;
        if (otherCount) removeCheckpointFiles(it->path().string());
      }
    }
  }
  // No rank writes before every rank has passed the checks and cleared its folder.
  MPI_Barrier(comm_);
}

void RankCheckpointStore::note(const std::string& text, bool alsoOnStderr) {
  if (std::find(notes().begin(), notes().end(), text) != notes().end()) return;  // said once
  if (alsoOnStderr) std::cerr << "rank " << rank_ << ": " << text << "\n";
  addNote(text);
}

std::vector<RankCheckpointStore::WholeFile> RankCheckpointStore::wholeFiles(int loop) {
  std::vector<WholeFile> whole;
  const std::string from = (fs::path(settings_.restartFolder) / rankCheckpointFolderName(rank_, ranks_)).string();
  for (const std::string& path : checkpointFiles(from, loop)) {
    try {
      const Checkpoint checkpoint = readCheckpointFile(path);
      if (checkpoint.sceneDigest != digest_)
        throw InputError("--restart", "checkpoint '" + path + "' belongs to another scene (digest " +
                                          checkpoint.sceneDigest + ", this scene's " + digest_ + ")");
      whole.push_back({checkpoint.step, path});
    } catch (const CorruptCheckpoint& e) {
      note(std::string("checkpoint skipped: ") + e.what(), true);
    }
  }
  return whole;  // newest first, as checkpointFiles lists them
}

long long RankCheckpointStore::commonStep(const std::vector<WholeFile>& whole) const {
  // Each round: the lowest of the ranks' newest steps not above `bound`; taken when every rank holds
  // it whole, else the next round looks below it. `bound` falls every round, so this ends.
  long long bound = LLONG_MAX;
  while (true) {
    long long mine = -1;
    for (const WholeFile& w : whole)
      if (w.step <= bound) {
        mine = w.step;
        break;
      }
    const long long low = reduce(mine, MPI_MIN, comm_);
    if (low < 0) return -1;
    const bool held = std::any_of(whole.begin(), whole.end(), [low](const WholeFile& w) { return w.step == low; });
    if (reduce(held ? 1 : 0, MPI_MIN, comm_) == 1) return low;
    bound = low - 1;
  }
}

std::optional<CheckpointPoint> RankCheckpointStore::resumePoint(int loop) {
  if (settings_.restartFolder.empty()) return std::nullopt;
  const std::string from = (fs::path(settings_.restartFolder) / rankCheckpointFolderName(rank_, ranks_)).string();
  const bool mineExist = !checkpointFiles(from, loop).empty();
  // Rank 0 alone decides for a loop it runs alone; otherwise every rank takes part.
  const bool anyExist = alone_ ? mineExist : reduce(mineExist ? 1 : 0, MPI_MAX, comm_) == 1;
  if (!anyExist) return std::nullopt;  // a loop the checkpointed run had not reached: it starts afresh
  const std::vector<WholeFile> whole = wholeFiles(loop);
  const long long step = alone_ ? (whole.empty() ? -1 : whole.front().step) : commonStep(whole);
  const std::string where = alone_ ? "rank 0" : "every one of the " + std::to_string(ranks_) + " ranks";
  // Ranks that went on from different steps would wait on one another in the first halo exchange
  // for ever: a clear error instead, should the agreement above ever fail.
  if (!alone_) {
    const long long low = reduce(step, MPI_MIN, comm_), high = reduce(step, MPI_MAX, comm_);
    if (low != high)
      throw Error("time loop " + std::to_string(loop) + ": the ranks would go on from steps " + std::to_string(low) +
                  " to " + std::to_string(high) + ", not one step");
  }
  if (step < 0) {
    note("time loop " + std::to_string(loop) + " starts again from its beginning: no checkpoint of it is whole on " +
             where,
         rank_ == 0);
    return std::nullopt;
  }
  const auto chosen =
      std::find_if(whole.begin(), whole.end(), [step](const WholeFile& w) { return w.step == step; });
  Checkpoint checkpoint = readCheckpointFile(chosen->path);
  CheckpointPoint point;
  point.step = checkpoint.step;
  point.time = checkpoint.time;
  point.archive = StateArchive(std::move(checkpoint.arrays));
  point.source = chosen->path;
  std::ostringstream text;
  text << "time loop " << loop << " resumed from step " << point.step << " (t = " << point.time << ") on " << where
       << " (" << point.source << ")";
  note(text.str(), false);
  return point;
}

void RankCheckpointStore::write(int loop, long step, Real time, const StateArchive& archive) {
  writeCheckpoint(rankFolder_, stateCheckpoint(digest_, step, time, archive, sceneText_), loop);
  if (!alone_) {
    // Every rank has renamed its file into place before the manifest names the step; the ranks step
    // in lockstep, so they all write the same step.
    const long long low = reduce(step, MPI_MIN, comm_), high = reduce(step, MPI_MAX, comm_);
    if (low != high)
      throw Error("checkpoint of time loop " + std::to_string(loop) + ": the ranks wrote steps " +
                  std::to_string(low) + " to " + std::to_string(high) + ", not one step");
  }
  if (rank_ != 0) return;
  CheckpointManifest manifest;
  manifest.ranks = ranks_;
  manifest.sceneDigest = digest_;
  manifest.loop = loop;
  manifest.step = step;
  manifest.time = time;
  manifest.rankZeroAlone = alone_;
  for (int r = 0; r < (alone_ ? 1 : ranks_); ++r)
    manifest.files.push_back(rankCheckpointFolderName(r, ranks_) + "/" + checkpointFileName(loop, step));
  writeCheckpointManifest(folder_, manifest);
}

std::shared_ptr<CheckpointStore> makeRankCheckpointStore(const std::string& folder, const std::string& sceneDigest,
                                                         const CheckpointSettings& settings,
                                                         const std::string& sceneText) {
  return std::make_shared<RankCheckpointStore>(folder, sceneDigest, settings, sceneText, MPI_COMM_WORLD);
}

RankAwareStoreMaker rankAwareCheckpointStoreMaker() {
  // MpiSession::size(): 1 when no launcher started MPI (a plain run of an MPI build).
  return MpiSession::size() > 1 ? RankAwareStoreMaker(makeRankCheckpointStore) : RankAwareStoreMaker();
}

RankZeroAloneLoop::RankZeroAloneLoop() {
  auto* store = dynamic_cast<RankCheckpointStore*>(checkpointStore());
  if (!store) return;
  if (store->rank() != 0) {
    store->claimLoop();  // the loop rank 0 runs: its number is taken here too
    return;
  }
  store_ = store;
  store_->setRankZeroAlone(true);
}

RankZeroAloneLoop::~RankZeroAloneLoop() {
  if (store_) store_->setRankZeroAlone(false);
}

}  // namespace mfwave
