#include "geometry/ExtrudedPolygon.hpp"

#include "core/Error.hpp"
#include "geometry/SolidName.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace mfwave {

ExtrudedPolygon::ExtrudedPolygon(std::vector<Vec2> vertices, Real z0, Real z1, const std::string& name)
    : name_(checkedSolidName(name, "extruded_polygon")),
      shape_(std::move(vertices), solidKey(name_, "extruded_polygon", "vertices")),
      z0_(z0),
      z1_(z1) {
  if (!std::isfinite(z0) || !std::isfinite(z1) || !(z1 > z0))
    throw InputError(solidKey(name_, "extruded_polygon", "z1"),
                     "must be finite and above z0 = " + std::to_string(z0) + ", got " + std::to_string(z1));
}

Real ExtrudedPolygon::signedDistance(const Vec3& x) const {
  const Real wall = shape_.signedDistance(x.head<2>());
  const Real slab = std::abs(x.z() - 0.5 * (z0_ + z1_)) - 0.5 * (z1_ - z0_);
  const Real outside = std::hypot(std::max(wall, 0.0), std::max(slab, 0.0));
  return outside + std::min(std::max(wall, slab), 0.0);
}

ExtrudedPolygon::ActiveSurface ExtrudedPolygon::active(const Vec3& x) const {
  const PlanarPolygon::NearestEdge nearest = shape_.nearestEdge(x.head<2>());
  const Real wall = shape_.contains(x.head<2>()) ? -nearest.distance : nearest.distance;
  const Real slab = std::abs(x.z() - 0.5 * (z0_ + z1_)) - 0.5 * (z1_ - z0_);
  if (wall >= slab) return {-1, nearest.edge};
  return {x.z() < 0.5 * (z0_ + z1_) ? 0 : 1, nearest.edge};
}

Vec3 ExtrudedPolygon::normal(const Vec3& x) const {
  const ActiveSurface s = active(x);
  if (s.cap == 0) return -Vec3::UnitZ();
  if (s.cap == 1) return Vec3::UnitZ();
  const Vec2& n = shape_.outwardNormal(s.edge);
  return Vec3(n.x(), n.y(), 0.0);
}

Bounds<3> ExtrudedPolygon::bounds() const {
  const Bounds<2> flat = shape_.bounds();
  Bounds<3> b;
  b.lower = Vec3(flat.lower.x(), flat.lower.y(), z0_);
  b.upper = Vec3(flat.upper.x(), flat.upper.y(), z1_);
  return b;
}

std::string ExtrudedPolygon::surfaceName(const Vec3& x) const {
  const ActiveSurface s = active(x);
  if (s.cap == 0) return qualifiedSurfaceName(name_, "bottom");
  if (s.cap == 1) return qualifiedSurfaceName(name_, "top");
  return qualifiedSurfaceName(name_, "edge" + std::to_string(s.edge));
}

}  // namespace mfwave
