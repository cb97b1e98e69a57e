#pragma once
// An observer that renders every n-th state it is shown to a PNG picture. Where no display is
// available (a batch node without X) it renders nothing, records why once and lets the run go
// on, so the .vtp and CSV output of the same run is still written; the driver reports
// skippedReason() at the end.

#include "io/vtk/PngRenderer.hpp"
#include "io/vtk/StateFrame.hpp"
#include "observers/Observer.hpp"

#include <string>

namespace mfwave {

template <int D>
class PngFrameRenderer : public Observer {
 public:
  // Pictures go to "<folder>/<base>_<NNNNNN>.png", NNNNNN counting the states observed (from
  // 0), so they carry the numbers of the .vtp frames of a VtkFrameWriter added with the same
  // interval; only every `every`-th observed state is rendered (rendering costs ~1 s a frame
  // under a software GL). `components` and `extra` are as for VtkFrameWriter. The folder is
  // created if missing; the particle set must outlive the renderer.
  PngFrameRenderer(const ParticleSet<D>& particles, std::string folder, std::string base, int components,
                   PngOptions options = {}, long every = 1, ExtraFields extra = {});

  // Renders when due; skips silently once no display was found. Throws Error for other
  // failures (missing field, unwritable folder).
  void observe(const StateView& state) override;

  long framesRendered() const { return rendered_; }
  // Why no pictures are made ("no DISPLAY set: run under xvfb-run -a ..."); empty while rendering works.
  const std::string& skippedReason() const { return skipped_; }
  const std::string& lastImagePath() const { return lastImage_; }
  // The counts of states seen and pictures rendered (the display is asked again after a restart).
  void saveState(StateArchive& archive) const override;
  void restoreState(const StateArchive& archive) override;

 private:
  const ParticleSet<D>& particles_;
  std::string folder_;
  std::string base_;
  int components_;
  PngRenderer renderer_;
  long every_;
  ExtraFields extra_;
  long observed_ = 0;
  long rendered_ = 0;
  bool displayChecked_ = false;
  std::string skipped_;
  std::string lastImage_;
};

extern template class PngFrameRenderer<1>;
extern template class PngFrameRenderer<2>;
extern template class PngFrameRenderer<3>;

}  // namespace mfwave
