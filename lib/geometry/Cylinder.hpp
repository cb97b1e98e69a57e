#pragma once
// A capped circular cylinder in 3-D: the points within `radius` of the segment from `bottom` to
// `top` whose projection falls between them. Its surfaces are "side", "bottom" (the disc at the
// first end point) and "top".
//
// In the coordinates (distance from the axis, position along it) the cylinder is a rectangle, so
// its exact signed distance is a 2-D box's.

#include "geometry/Solid.hpp"

#include <string>

namespace mfwave {

class Cylinder final : public Solid<3> {
 public:
  // Throws InputError "<name or cylinder>.radius" (not positive and finite), ".top" (the end
  // points coincide) or ".bottom" / ".top" (not finite).
  Cylinder(const Vec3& bottom, const Vec3& top, Real radius, const std::string& name = "");

  Real signedDistance(const Vec3& x) const override;
  Vec3 normal(const Vec3& x) const override;
  Bounds<3> bounds() const override;
  std::string surfaceName(const Vec3& x) const override;

 private:
  enum class Part { Side, Bottom, Top };
  // Radial offset from the axis, and where x sits along it (0 at bottom, length_ at top).
  struct AxisFrame {
    Vec3 radial;
    Real along;
  };
  AxisFrame frame(const Vec3& x) const;
  Part activePart(const AxisFrame& f) const;

  Vec3 bottom_;
  Vec3 axis_;  // unit, bottom to top
  Real length_;
  Real radius_;
  std::string name_;
};

}  // namespace mfwave
