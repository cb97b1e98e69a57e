#pragma once
// An observer that writes every state it is shown as a .vtp frame and keeps the .pvd collection
// of the series up to date, so a run (even an interrupted one) opens in ParaView as one
// time-dependent data set.

#include "io/vtk/PvdCollection.hpp"
#include "io/vtk/StateFrame.hpp"
#include "observers/Observer.hpp"

#include <string>

namespace mfwave {

template <int D>
class VtkFrameWriter : public Observer {
 public:
  // Frames go to "<folder>/<base>_<NNNNNN>.vtp" (NNNNNN counts the frames written, from 0) and
  // the collection to "<folder>/<base>.pvd"; the folder is created if missing. `components` is
  // the number of unknowns per particle in the state (dof = particle * components + component).
  // `extra` may append method fields (stress, density, ...) to every frame.
  // The particle set must outlive the writer; moved particles are written where they are.
  VtkFrameWriter(const ParticleSet<D>& particles, std::string folder, std::string base, int components,
                 ExtraFields extra = {});

  // Writes the frame of `state` and rewrites the .pvd. Throws Error if writing fails.
  void observe(const StateView& state) override;

  long framesWritten() const { return frames_; }
  const std::string& pvdPath() const { return collection_.path(); }
  // Path of the frame written last (empty before the first).
  const std::string& lastFramePath() const { return lastFrame_; }
  // The frames written so far (their times and files, for the .pvd): a restored run numbers its
  // next frame on and lists every frame, those before the checkpoint too.
  void saveState(StateArchive& archive) const override;
  void restoreState(const StateArchive& archive) override;

 private:
  const ParticleSet<D>& particles_;
  std::string folder_;
  std::string base_;
  int components_;
  ExtraFields extra_;
  PvdCollection collection_;
  long frames_ = 0;
  std::string lastFrame_;
};

extern template class VtkFrameWriter<1>;
extern template class VtkFrameWriter<2>;
extern template class VtkFrameWriter<3>;

}  // namespace mfwave
