#pragma once
// Off-screen PNG pictures of a ParticleFrame: particles as shaded spheres coloured by one field,
// with a colour bar and a title carrying the time. For quick looks and animations of a run;
// ParaView on the .vtp frames is the tool for anything more.

#include "core/Types.hpp"
#include "io/vtk/ParticleFrame.hpp"

#include <array>
#include <optional>
#include <string>

namespace mfwave {

// Any part left empty takes the default: for 3-D an isometric view from (+1,+1,+1) with z up,
// for 1-D and 2-D a parallel view from +z with y up, both fitted to the particle cloud.
struct PngCamera {
  std::optional<std::array<Real, 3>> position;
  std::optional<std::array<Real, 3>> focalPoint;
  std::optional<std::array<Real, 3>> viewUp;
};

struct PngOptions {
  static constexpr int magnitude = -1;

  std::string field = "velocity";  // the field that colours the particles
  int component = magnitude;       // 0-based component index, or magnitude (Euclidean norm)
  Real pointSize = 0;              // sphere diameter in pixels; 0 = 0.6 of the particle spacing on screen
  int width = 1024;
  int height = 768;
  PngCamera camera;
  bool colourBar = true;
  std::string colourBarTitle;  // empty: the field label ("velocity_z", "velocity magnitude")
  bool title = true;
  std::string titleText;       // empty: "<field label>  t = <time>"
  // Fixed colour range, so every picture of a series has the same scale; empty: the frame's
  // min..max (widened when all values are equal).
  std::optional<std::array<Real, 2>> range;
  // Fixed view box {xmin, xmax, ymin, ymax, zmin, zmax} that the camera frames instead of the
  // particles' bounds, so every picture of a series shows the same region while bodies move;
  // empty: fitted to the particles.
  std::optional<std::array<Real, 6>> window;
  std::array<Real, 3> background{1.0, 1.0, 1.0};  // white, black text
};

class PngRenderer {
 public:
  explicit PngRenderer(PngOptions options = {});

  // Whether rendering can work here (see renderDisplayAvailable): checked without touching VTK
  // rendering, so a run without X can skip pictures instead of being aborted by VTK.
  static bool displayAvailable(std::string* why = nullptr);

  // Renders `frame` to `path` (written to "<path>.tmp-<pid>.png", renamed when complete).
  // Throws Error when no display is available (with the reason), when the field is missing or
  // the component out of range, or when writing fails; it never lets VTK abort the process.
  template <int D>
  void render(const ParticleFrame<D>& frame, const std::string& path) const;

  const PngOptions& options() const { return options_; }

 private:
  PngOptions options_;
};

// "velocity_x", "stress_xy", "velocity magnitude", "pressure": how the colouring quantity is labelled.
std::string fieldLabel(const ParticleField& field, int component);

}  // namespace mfwave
