#pragma once
// [geometry]: an axis-aligned box filled with a lattice of particles, optional ghost layers and
// periodic axes. Vectors have one entry per axis (scene.dimension entries).

#include "core/Types.hpp"
#include "io/scene/SceneReader.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace mfwave {

struct GeometrySpec {
  int dimension = 0;
  std::string shape;               // "line", "rectangle" or "block", matching the dimension
  std::vector<Real> lower, upper;  // box corners
  Real spacing = 0;                // lattice spacing, divides every side
  std::vector<Index> intervals;    // lattice intervals per axis (side / spacing)
  int ghostLayers = 0;
  std::uint8_t ghostFaces = 0;     // BoxFace mask
  std::vector<bool> periodic;      // per axis

  // Physical lattice particles: the product of (intervals + 1).
  Index particleCount() const;
  // Whether x (one entry per axis) lies in the box, up to 1e-9 of each side.
  bool contains(const std::vector<Real>& x) const;
  // "[0, 1] x [0, 2]" for messages.
  std::string describeBox() const;
  // The same geometry on another box or spacing (resolution and domain studies): intervals are
  // recomputed. Throws InputError("geometry.spacing") when the spacing does not divide a side.
  GeometrySpec withLattice(const std::vector<Real>& newLower, const std::vector<Real>& newUpper,
                           Real newSpacing) const;
};

GeometrySpec readGeometry(SceneReader& reader, int dimension);

}  // namespace mfwave
