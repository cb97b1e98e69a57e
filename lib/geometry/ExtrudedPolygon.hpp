#pragma once
// A 3-D prism: a simple polygon in the x-y plane extruded along z from z0 to z1. Its surfaces are
// the side walls "edge<i>" (over the polygon's edge i), "bottom" (z = z0) and "top" (z = z1).
//
// In the coordinates (signed distance to the polygon in x-y, distance beyond the z slab) the prism
// is a quadrant, so its exact signed distance combines the two like a 2-D box's.

#include "geometry/PlanarPolygon.hpp"
#include "geometry/Solid.hpp"

#include <string>
#include <vector>

namespace mfwave {

class ExtrudedPolygon final : public Solid<3> {
 public:
  // Throws InputError "<name or extruded_polygon>.vertices" (as Polygon) or ".z1" unless
  // z0 < z1, both finite.
  ExtrudedPolygon(std::vector<Vec2> vertices, Real z0, Real z1, const std::string& name = "");

  Real signedDistance(const Vec3& x) const override;
  Vec3 normal(const Vec3& x) const override;
  Bounds<3> bounds() const override;
  std::string surfaceName(const Vec3& x) const override;

  const PlanarPolygon& shape() const { return shape_; }
  Real volume() const { return shape_.area() * (z1_ - z0_); }

 private:
  // -1: a wall (the nearest edge in `edge`), 0: bottom, 1: top.
  struct ActiveSurface {
    int cap;
    Index edge;
  };
  ActiveSurface active(const Vec3& x) const;

  std::string name_;
  PlanarPolygon shape_;
  Real z0_;
  Real z1_;
};

}  // namespace mfwave
