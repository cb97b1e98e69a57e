#pragma once
// What every driver with particle frames shares: the picture settings the scene's [output]
// section asks for, and the summary lines of the frames a run wrote (how many, or why no PNG).

#include "io/scene/OutputSpec.hpp"
#include "io/vtk/PngFrameRenderer.hpp"
#include "io/vtk/VtkFrameWriter.hpp"

#include <optional>
#include <string>
#include <vector>

namespace mfwave {

// [output]'s png_field, png_component, png_point_size, png_width and png_height as PngOptions;
// a driver adds what only it knows (a fixed colour range, a point size fitted to its geometry).
PngOptions pngOptionsFor(const OutputSpec& output);

// The summary's lines for a series named `base`: "<base>.pvd (N frames)" and
// "<base>_*.png (N images)" as files, or the reason no picture was rendered as a note.
struct FrameOutputReport {
  std::vector<std::string> files;
  std::vector<std::string> notes;

  // Appends the lines to a case's own lists.
  void appendTo(std::vector<std::string>& caseFiles, std::vector<std::string>& caseNotes) const {
    caseFiles.insert(caseFiles.end(), files.begin(), files.end());
    caseNotes.insert(caseNotes.end(), notes.begin(), notes.end());
  }
};

template <int D>
FrameOutputReport frameOutputReport(const std::string& base, const std::optional<VtkFrameWriter<D>>& frames,
                                    const std::optional<PngFrameRenderer<D>>& images) {
  FrameOutputReport report;
  if (frames) report.files.push_back(base + ".pvd (" + std::to_string(frames->framesWritten()) + " frames)");
  if (images) {
    if (images->skippedReason().empty())
      report.files.push_back(base + "_*.png (" + std::to_string(images->framesRendered()) + " images)");
    else
      report.notes.push_back("no PNG frames: " + images->skippedReason());
  }
  return report;
}

// The particle frames of one series `base` a run writes: the VTK series (<base>_NNNNNN.vtp and
// <base>.pvd) and the PNG pictures (<base>_NNNNNN.png) as asked, both of the same particle set
// (which a ViewAdapter may keep at the current positions). attachTo adds them to whatever shows
// them the state (a TimeLoop, or a ViewAdapter for a first-order method); report() is the
// summary's lines for them.
template <int D>
class ParticleFrames {
 public:
  struct Settings {
    bool vtk = false;
    bool png = false;
    PngOptions pngOptions;
    long pngEvery = 1;       // a picture every n-th time the renderer is due
    ExtraFields extra;       // fields beyond u and v in every frame and picture
    int components = D;      // of u and v per particle in the view
  };

  // The particle set must outlive the frames.
  ParticleFrames(const ParticleSet<D>& particles, const std::string& folder, const std::string& base,
                 const Settings& settings)
      : base_(base) {
    if (settings.vtk) vtk_.emplace(particles, folder, base, settings.components, settings.extra);
    if (settings.png)
      png_.emplace(particles, folder, base, settings.components, settings.pngOptions, settings.pngEvery,
                   settings.extra);
  }

  template <class Host>
  void attachTo(Host& host, long every) {
    if (vtk_) host.add(*vtk_, every);
    if (png_) host.add(*png_, every);
  }

  FrameOutputReport report() const { return frameOutputReport(base_, vtk_, png_); }

 private:
  std::string base_;
  std::optional<VtkFrameWriter<D>> vtk_;
  std::optional<PngFrameRenderer<D>> png_;
};

// The frames [output] asks for (vtk, png with pngOptionsFor), or none when `wanted` is false (a
// case that writes no frames).
template <int D>
typename ParticleFrames<D>::Settings frameSettings(const OutputSpec& output, bool wanted = true) {
  typename ParticleFrames<D>::Settings settings;
  settings.vtk = wanted && output.vtk;
  settings.png = wanted && output.png;
  settings.pngOptions = pngOptionsFor(output);
  return settings;
}

}  // namespace mfwave
