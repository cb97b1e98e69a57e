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

}  // namespace mfwave
