#include "io/vtk/VtkFrameWriter.hpp"

#include "core/Error.hpp"
#include "io/vtk/VtpWriter.hpp"

#include <filesystem>

namespace mfwave {

template <int D>
VtkFrameWriter<D>::VtkFrameWriter(const ParticleSet<D>& particles, std::string folder, std::string base,
                                  int components, ExtraFields extra)
    : particles_(particles),
      folder_(std::move(folder)),
      base_(std::move(base)),
      components_(components),
      extra_(std::move(extra)),
      collection_((std::filesystem::path(folder_) / (base_ + ".pvd")).string()) {
  if (base_.empty()) throw Error("VTK frame output: the base name is empty");
  if (components_ < 1)
    throw Error("VTK frame output: components per particle must be at least 1, got " + std::to_string(components_));
  // Created up front so a bad folder fails before the run starts, not at the first frame.
  ensureFolder(folder_);
}

template <int D>
void VtkFrameWriter<D>::observe(const StateView& state) {
  const ParticleFrame<D> frame = frameFromState(particles_, state, components_, extra_);
  const std::string path = frameFilePath(folder_, base_, frames_, ".vtp");
  VtpWriter::write(frame, path);
  collection_.add(state.time, path);
  lastFrame_ = path;
  ++frames_;
}

template <int D>
void VtkFrameWriter<D>::saveState(StateArchive& archive) const {
  std::vector<Real> times;
  std::string files;
  for (const PvdCollection::Entry& entry : collection_.entries()) {
    times.push_back(entry.time);
    files += entry.file + '\n';
  }
  archive.put("times", std::move(times));
  archive.putText("files", files);
}

template <int D>
void VtkFrameWriter<D>::restoreState(const StateArchive& archive) {
  const std::vector<Real>& times = archive.get("times");
  const std::string files = archive.text("files");
  std::vector<PvdCollection::Entry> entries;
  std::size_t from = 0;
  for (const Real time : times) {
    const std::size_t to = files.find('\n', from);
    if (to == std::string::npos) throw InputError("--restart", "the checkpoint's VTK frame list is shorter than its times");
    entries.push_back({time, files.substr(from, to - from)});
    from = to + 1;
  }
  if (from != files.size()) throw InputError("--restart", "the checkpoint's VTK frame list is longer than its times");
  frames_ = static_cast<long>(entries.size());
  lastFrame_ = frames_ > 0 ? frameFilePath(folder_, base_, frames_ - 1, ".vtp") : std::string();
  collection_.restore(std::move(entries));
}

template class VtkFrameWriter<1>;
template class VtkFrameWriter<2>;
template class VtkFrameWriter<3>;

}  // namespace mfwave
