#pragma once
// Faces of an axis-aligned box and the bit masks that record which faces a particle lies on.
// Boundary conditions need to know, per particle, which face(s) it belongs to: a particle on an
// edge or a corner belongs to two or three faces at once, so the information is a bit set rather
// than a single face number. The numbering 2*axis + (0 for the low side, 1 for the high side)
// makes axis and side recoverable by arithmetic.

#include "core/Types.hpp"

#include <cstdint>

namespace mfwave {

enum class BoxFace : std::uint8_t { MinusX = 0, PlusX = 1, MinusY = 2, PlusY = 3, MinusZ = 4, PlusZ = 5 };

// Bit of `face` in a face mask.
constexpr std::uint8_t faceBit(BoxFace face) {
  return static_cast<std::uint8_t>(1u << static_cast<unsigned>(face));
}
constexpr std::uint8_t faceBit(int face) { return static_cast<std::uint8_t>(1u << face); }

// Mask with every face of a D-dimensional box set (2*D faces).
constexpr std::uint8_t allFaces(int dimension) {
  return static_cast<std::uint8_t>((1u << (2 * dimension)) - 1u);
}

// Axis the face is perpendicular to (0 = x, 1 = y, 2 = z).
constexpr int faceAxis(int face) { return face / 2; }
// -1 for the low face of an axis, +1 for the high face: the sign of its outward normal.
constexpr int faceSign(int face) { return face % 2 == 0 ? -1 : 1; }

// Unit outward normal of face `face` (0 <= face < 2*D).
template <int D>
Vec<D> faceNormal(int face) {
  Vec<D> n = Vec<D>::Zero();
  n[faceAxis(face)] = faceSign(face);
  return n;
}

// Axis letter for messages ("x", "y", "z").
inline const char* axisName(int axis) {
  static const char* const names[] = {"x", "y", "z"};
  return names[axis];
}

}  // namespace mfwave
