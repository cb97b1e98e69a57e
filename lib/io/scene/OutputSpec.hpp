#pragma once
// [output]: where results go and which are written.

#include "io/scene/SceneReader.hpp"

#include <string>

namespace mfwave {

struct OutputSpec {
  std::string folder;        // default out/<scene.name>
  long every = 10;           // steps between VTK / PNG frames
  bool vtk = false;
  bool png = false;          // PNG frames every `every` steps, with or without VTK
  std::string pngField = "velocity";       // "displacement" | "velocity"
  std::string pngComponent = "magnitude";  // "x" | "y" | "z" | "magnitude"
  int pngComponentIndex = -1;              // 0, 1, 2 for x, y, z; -1 for the magnitude
  Real pngPointSize = 6;
  int pngWidth = 1024, pngHeight = 768;
  long probeEvery = 1;       // steps between probe samples
  bool energy = true;
  // Checkpoints (read again from the resolved scene by io/run's prepareOutputFolder, which installs
  // the store; --checkpoint-every overrides both).
  long checkpointEvery = 0;      // steps between checkpoints (0: none)
  Real checkpointSeconds = 0;    // wall-clock seconds between checkpoints (0: none)

  bool writesFrames() const { return vtk || png; }
};

OutputSpec readOutput(SceneReader& reader, const std::string& sceneName, int dimension);

}  // namespace mfwave
