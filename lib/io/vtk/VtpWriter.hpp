#pragma once
// Writes one ParticleFrame as a VTK XML PolyData file (.vtp) that ParaView opens directly.

#include "io/vtk/ParticleFrame.hpp"

#include <string>

namespace mfwave {

class VtpWriter {
 public:
  // Writes `frame` to `path` (conventionally ending in .vtp): points padded to 3-D, one vertex
  // cell per particle, every field as point data (vectors padded to 3 components), the time as
  // field data "TimeValue". Raw binary appended data compressed with zlib, with 64-bit block
  // headers: the smallest files VTK writes, still portable, and no base64 cost.
  // Written to "<path>.tmp-<pid>.vtp" and renamed onto `path` only when complete, so an
  // interrupted run never leaves a truncated frame. Throws Error naming the path on failure
  // (the temporary is removed) and for an inconsistent frame (see checkFrame).
  template <int D>
  static void write(const ParticleFrame<D>& frame, const std::string& path);
};

}  // namespace mfwave
