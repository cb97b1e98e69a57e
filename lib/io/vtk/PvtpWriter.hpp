#pragma once
// Writes the master file (.pvtp) of a frame split into .vtp pieces, one per rank of a distributed
// run, so ParaView opens the pieces as one data set. Plain XML written here rather than through
// vtkXMLPPolyDataWriter: that writer lives in VTK's parallel modules and writes the pieces too,
// while here each rank writes its own piece and rank 0 only needs the list of them.

#include "io/vtk/ParticleFrame.hpp"

#include <string>
#include <vector>

namespace mfwave {

class PvtpWriter {
 public:
  // Writes `path` (conventionally ending in .pvtp) declaring the point arrays of `fields` as
  // VtpWriter writes them (Float64, vectors padded to 3 components: every piece must carry the
  // same fields, so any piece's fields describe them all), Float64 3-D points, and one Piece per
  // entry of `pieces` (paths as the caller opens them, stored relative to the master's folder),
  // in order. Written through AtomicFile. Throws Error for no pieces, for an inconsistent field
  // (empty or repeated name, a scalar with several components, a vector with more than 3) and
  // when the file cannot be written. Does not check that the pieces exist: other processes may
  // still be writing them.
  static void write(const std::vector<ParticleField>& fields, const std::vector<std::string>& pieces,
                    const std::string& path);
};

}  // namespace mfwave
