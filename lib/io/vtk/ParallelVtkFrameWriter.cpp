#include "io/vtk/ParallelVtkFrameWriter.hpp"

#include "core/Error.hpp"
#include "io/vtk/PvtpWriter.hpp"
#include "io/vtk/VtpWriter.hpp"

#include <filesystem>

namespace mfwave {

template <int D>
ParallelVtkFrameWriter<D>::ParallelVtkFrameWriter(const ParticleSet<D>& particles, std::vector<Index> owned,
                                                  std::string folder, std::string base, int components, int rank,
                                                  int rankCount, ExtraFields extra)
    : particles_(particles),
      owned_(std::move(owned)),
      folder_(std::move(folder)),
      base_(std::move(base)),
      components_(components),
      rank_(rank),
      rankCount_(rankCount),
      extra_(std::move(extra)),
      collection_((std::filesystem::path(folder_) / (base_ + ".pvd")).string()) {
  if (base_.empty()) throw Error("parallel VTK frame output: the base name is empty");
  if (components_ < 1)
    throw Error("parallel VTK frame output: components per particle must be at least 1, got " +
                std::to_string(components_));
  if (rankCount_ < 1) throw InputError("rankCount", "must be at least 1, got " + std::to_string(rankCount_));
  if (rank_ < 0 || rank_ >= rankCount_)
    throw InputError("rank", std::to_string(rank_) + " is outside [0, " + std::to_string(rankCount_) + ")");
  // Checked here, not when the first frame is written, so a bad split fails before the run.
  const Index size = particles_.size();
  std::vector<Index> seenAt(static_cast<std::size_t>(size), -1);
  for (std::size_t k = 0; k < owned_.size(); ++k) {
    const Index i = owned_[k];
    if (i < 0 || i >= size)
      throw InputError("owned", "entry " + std::to_string(k) + " is particle " + std::to_string(i) +
                                    ", outside the " + std::to_string(size) + " particles");
    Index& seen = seenAt[static_cast<std::size_t>(i)];
    if (seen >= 0)
      throw InputError("owned", "particle " + std::to_string(i) + " is listed twice (entries " +
                                    std::to_string(seen) + " and " + std::to_string(k) + ")");
    seen = static_cast<Index>(k);
  }
  ensureFolder(folder_);
}

template <int D>
std::string ParallelVtkFrameWriter<D>::piecePath(long frame, int pieceRank) const {
  return frameFilePath(folder_, base_, frame, "_" + std::to_string(pieceRank) + ".vtp");
}

template <int D>
std::string ParallelVtkFrameWriter<D>::masterPath(long frame) const {
  return frameFilePath(folder_, base_, frame, ".pvtp");
}

template <int D>
void ParallelVtkFrameWriter<D>::observe(const StateView& state) {
  const ParticleFrame<D> frame = frameFromState(particles_, owned_, state, components_, extra_);
  VtpWriter::write(frame, piecePath(frames_, rank_));
  if (rank_ == 0) {
    std::vector<std::string> pieces;
    for (int r = 0; r < rankCount_; ++r) pieces.push_back(piecePath(frames_, r));
    PvtpWriter::write(frame.fields, pieces, masterPath(frames_));
    collection_.add(state.time, masterPath(frames_));
  }
  times_.push_back(state.time);
  ++frames_;
}

template <int D>
void ParallelVtkFrameWriter<D>::saveState(StateArchive& archive) const {
  archive.put("times", times_);
}

template <int D>
void ParallelVtkFrameWriter<D>::restoreState(const StateArchive& archive) {
  times_ = archive.get("times");
  frames_ = static_cast<long>(times_.size());
  std::vector<PvdCollection::Entry> entries;
  for (long f = 0; f < frames_; ++f)
    entries.push_back({times_[static_cast<std::size_t>(f)],
                       std::filesystem::path(masterPath(f)).filename().string()});
  collection_.restore(std::move(entries));
}

template class ParallelVtkFrameWriter<1>;
template class ParallelVtkFrameWriter<2>;
template class ParallelVtkFrameWriter<3>;

}  // namespace mfwave
