#pragma once
// The frame observer of a run split over ranks: each rank writes the particles it owns as one
// .vtp piece per frame; rank 0 also writes the frame's .pvtp master listing every piece and keeps
// the .pvd collection of the masters, so ParaView opens the whole series as one time-dependent
// data set. Knows nothing of MPI (lib/io/vtk does not link it): the rank and the rank count are
// plain numbers and the piece names follow from them, so no rank needs to hear from another.
//
// Files of frame NNNNNN (counted from 0, zero-padded) in `folder`:
//   <base>_<NNNNNN>_<rank>.vtp   one piece per rank, written by that rank
//   <base>_<NNNNNN>.pvtp         the master, rank 0, pieces listed in rank order
//   <base>.pvd                   the collection of the masters with their times, rank 0
// All in one folder, so the relative names in the .pvtp and the .pvd hold wherever it is copied.

#include "io/vtk/PvdCollection.hpp"
#include "io/vtk/StateFrame.hpp"
#include "observers/Observer.hpp"

#include <string>
#include <vector>

namespace mfwave {

template <int D>
class ParallelVtkFrameWriter : public Observer {
 public:
  // `owned[k]` is the index in `particles` of the k-th node of this rank's state (dof = k *
  // components + component); the state shown to observe() holds exactly these nodes. `extra`
  // is called with that state and owned.size(), so it appends the owned nodes' fields; every
  // rank must append the same fields (the master declares rank 0's). The particle set and the
  // folder are as for VtkFrameWriter (the folder is created if missing, on every rank).
  // Throws InputError naming "rankCount" (below 1), "rank" (outside [0, rankCount)) or "owned"
  // (an index outside the particles, or repeated), Error for an empty base or components < 1.
  // That the ranks' owned sets are disjoint and cover the particles is the caller's to ensure.
  ParallelVtkFrameWriter(const ParticleSet<D>& particles, std::vector<Index> owned, std::string folder,
                         std::string base, int components, int rank, int rankCount, ExtraFields extra = {});

  // Writes this rank's piece of `state`; rank 0 also writes the master and rewrites the .pvd.
  // Rank 0 does not wait for the other pieces: a reader that must see a complete frame
  // (a driver, a test) synchronises the ranks after observe(). Throws Error if writing fails or
  // the state does not hold owned.size() * components values.
  void observe(const StateView& state) override;

  long framesWritten() const { return frames_; }
  int rank() const { return rank_; }
  int rankCount() const { return rankCount_; }
  // The files of frame `frame` (see the layout above), whether written yet or not.
  std::string piecePath(long frame, int pieceRank) const;
  std::string masterPath(long frame) const;
  // Written by rank 0 only.
  const std::string& pvdPath() const { return collection_.path(); }

  // The times of the frames written so far. Every rank saves them; a restored run numbers its
  // next frame on, and rank 0's .pvd lists the frames before the checkpoint too (their names
  // follow from the numbering). A restart must use the same rank count.
  void saveState(StateArchive& archive) const override;
  void restoreState(const StateArchive& archive) override;

 private:
  const ParticleSet<D>& particles_;
  std::vector<Index> owned_;
  std::string folder_;
  std::string base_;
  int components_;
  int rank_;
  int rankCount_;
  ExtraFields extra_;
  PvdCollection collection_;  // written only on rank 0
  std::vector<Real> times_;
  long frames_ = 0;
};

extern template class ParallelVtkFrameWriter<1>;
extern template class ParallelVtkFrameWriter<2>;
extern template class ParallelVtkFrameWriter<3>;

}  // namespace mfwave
