#include "io/vtk/FrameOutputs.hpp"

namespace mfwave {

PngOptions pngOptionsFor(const OutputSpec& output) {
  PngOptions png;
  png.field = output.pngField;
  png.component = output.pngComponentIndex < 0 ? PngOptions::magnitude : output.pngComponentIndex;
  png.pointSize = output.pngPointSize;
  png.width = output.pngWidth;
  png.height = output.pngHeight;
  return png;
}

}  // namespace mfwave
