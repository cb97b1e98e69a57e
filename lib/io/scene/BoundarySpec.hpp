#pragma once
// [[boundary]]: conditions on box faces. Each face is in at most one entry; faces not named are
// free; faces of periodic axes take no condition. A "symmetry" face is a mirror plane (zero normal
// displacement, zero tangential traction): the box is one side of a solid symmetric about it, loaded
// symmetrically (at most one symmetry face per axis).

#include "core/TimeFunction.hpp"
#include "io/scene/GeometrySpec.hpp"
#include "io/scene/SceneReader.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace mfwave {

enum class BoundaryType { Free, Fixed, Traction, Displacement, Transmitting, Symmetry };

// "free", "fixed", "traction", "displacement", "transmitting", "symmetry".
std::string boundaryTypeName(BoundaryType type);

struct BoundarySpec {
  std::vector<int> faces;    // BoxFace numbers, in the order given
  std::uint8_t faceMask = 0; // the same as a mask
  BoundaryType type = BoundaryType::Free;
  std::vector<Real> traction;  // Traction: Pa, one entry per axis
  std::vector<Real> value;     // Displacement: m, one entry per axis
  TimeFunction timeFunction = TimeFunction::constant(1);  // Traction and Displacement
};

std::vector<BoundarySpec> readBoundaries(SceneReader& reader, const GeometrySpec& geometry);

// Mask of the faces that carry a condition of `type`.
std::uint8_t facesWith(const std::vector<BoundarySpec>& boundaries, BoundaryType type);

}  // namespace mfwave
