#pragma once
// A solid of the scene: the region a body occupies, described by what a particle fill, a lattice
// and boundary conditions ask of it. Primitives (box, ball, polygon, mesh, ...) and their CSG
// combinations implement it; a particle method never sees which one it is.
//
// Why a signed distance: one function answers inside/outside, how far the surface is (which a fill
// uses to skip cells the surface cannot reach) and, with the normal, where the surface cuts a
// small cell. Primitives return the exact distance; CSG returns min / max of its operands', which
// is exact on the surface, has the right sign, and never exceeds the true distance in magnitude.
// That last property is what makes a cell whose centre is farther than its half diagonal safely
// all inside or all outside.

#include "core/Types.hpp"
#include "geometry/Bounds.hpp"

#include <string>

namespace mfwave {

template <int D>
class Solid {
 public:
  virtual ~Solid() = default;

  // Negative inside, positive outside, zero on the surface. |value| never exceeds the distance to
  // the surface (and equals it for every primitive).
  virtual Real signedDistance(const Vec<D>& x) const = 0;
  // Inside or on the surface.
  bool inside(const Vec<D>& x) const { return signedDistance(x) <= 0; }
  // Unit outward normal of the surface nearest x (of the face that is nearest, or active in a CSG,
  // where edges and corners leave the normal undefined: the face surfaceName(x) names).
  virtual Vec<D> normal(const Vec<D>& x) const = 0;
  // A box holding the solid (infinite for a half-space).
  virtual Bounds<D> bounds() const = 0;
  // Name of the named surface nearest x: "<primitive name>.<surface>" when the primitive was given
  // a name, else the surface's own ("+z", "surface", "edge2", ...).
  virtual std::string surfaceName(const Vec<D>& x) const = 0;

 protected:
  Solid() = default;
  Solid(const Solid&) = default;
  Solid(Solid&&) = default;
  Solid& operator=(const Solid&) = default;
  Solid& operator=(Solid&&) = default;
};

}  // namespace mfwave
