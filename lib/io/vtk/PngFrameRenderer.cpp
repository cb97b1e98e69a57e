#include "io/vtk/PngFrameRenderer.hpp"

#include "core/Error.hpp"

namespace mfwave {

template <int D>
PngFrameRenderer<D>::PngFrameRenderer(const ParticleSet<D>& particles, std::string folder, std::string base,
                                      int components, PngOptions options, long every, ExtraFields extra)
    : particles_(particles),
      folder_(std::move(folder)),
      base_(std::move(base)),
      components_(components),
      renderer_(std::move(options)),
      every_(every),
      extra_(std::move(extra)) {
  if (base_.empty()) throw Error("PNG frame output: the base name is empty");
  if (components_ < 1)
    throw Error("PNG frame output: components per particle must be at least 1, got " + std::to_string(components_));
  if (every_ < 1) throw Error("PNG frame output: render every n-th frame needs n >= 1, got " + std::to_string(every_));
  ensureFolder(folder_);
}

template <int D>
void PngFrameRenderer<D>::observe(const StateView& state) {
  const long number = observed_++;
  if (number % every_ != 0) return;
  // Asked once: a display does not come and go during a run, and the check opens a connection.
  if (!displayChecked_) {
    displayChecked_ = true;
    std::string why;
    if (!PngRenderer::displayAvailable(&why)) skipped_ = why;
  }
  if (!skipped_.empty()) return;
  const ParticleFrame<D> frame = frameFromState(particles_, state, components_, extra_);
  const std::string path = frameFilePath(folder_, base_, number, ".png");
  renderer_.render(frame, path);
  lastImage_ = path;
  ++rendered_;
}

template <int D>
void PngFrameRenderer<D>::saveState(StateArchive& archive) const {
  archive.put("counts", std::vector<Real>{static_cast<Real>(observed_), static_cast<Real>(rendered_)});
}

template <int D>
void PngFrameRenderer<D>::restoreState(const StateArchive& archive) {
  const std::vector<Real>& counts = archive.numbers("counts", 2);
  observed_ = static_cast<long>(counts[0]);
  rendered_ = static_cast<long>(counts[1]);
  lastImage_ = rendered_ > 0 ? frameFilePath(folder_, base_, ((observed_ - 1) / every_) * every_, ".png") : std::string();
}

template class PngFrameRenderer<1>;
template class PngFrameRenderer<2>;
template class PngFrameRenderer<3>;

}  // namespace mfwave
