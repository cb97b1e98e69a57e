#include "geometry/Cylinder.hpp"

#include "core/Error.hpp"
#include "geometry/SolidName.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace mfwave {

Cylinder::Cylinder(const Vec3& bottom, const Vec3& top, Real radius, const std::string& name)
    : bottom_(bottom), radius_(radius), name_(checkedSolidName(name, "cylinder")) {
  if (!bottom.allFinite()) throw InputError(solidKey(name_, "cylinder", "bottom"), "must be finite");
  if (!top.allFinite()) throw InputError(solidKey(name_, "cylinder", "top"), "must be finite");
  if (!(radius > 0) || !std::isfinite(radius))
    throw InputError(solidKey(name_, "cylinder", "radius"), "must be positive and finite, got " + std::to_string(radius));
  length_ = (top - bottom).norm();
  if (!(length_ > 0)) throw InputError(solidKey(name_, "cylinder", "top"), "coincides with bottom: the axis has no length");
  axis_ = (top - bottom) / length_;
}

Cylinder::AxisFrame Cylinder::frame(const Vec3& x) const {
  const Vec3 offset = x - bottom_;
  const Real along = offset.dot(axis_);
  return {offset - along * axis_, along};
}

Cylinder::Part Cylinder::activePart(const AxisFrame& f) const {
  const Real radialExcess = f.radial.norm() - radius_;
  const Real axialExcess = std::abs(f.along - 0.5 * length_) - 0.5 * length_;
  if (radialExcess >= axialExcess) return Part::Side;
  return f.along < 0.5 * length_ ? Part::Bottom : Part::Top;
}

Real Cylinder::signedDistance(const Vec3& x) const {
  const AxisFrame f = frame(x);
  const Real radialExcess = f.radial.norm() - radius_;
  const Real axialExcess = std::abs(f.along - 0.5 * length_) - 0.5 * length_;
  const Real outside = std::hypot(std::max(radialExcess, 0.0), std::max(axialExcess, 0.0));
  return outside + std::min(std::max(radialExcess, axialExcess), 0.0);
}

Vec3 Cylinder::normal(const Vec3& x) const {
  const AxisFrame f = frame(x);
  switch (activePart(f)) {
    case Part::Bottom:
      return -axis_;
    case Part::Top:
      return axis_;
    case Part::Side:
      break;
  }
  const Real r = f.radial.norm();
  if (r > 0) return f.radial / r;
  // On the axis every radial direction is as near: any unit vector across the axis.
  const Vec3 across = std::abs(axis_.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  return (across - across.dot(axis_) * axis_).normalized();
}

Bounds<3> Cylinder::bounds() const {
  // Each end disc reaches radius * sqrt(1 - axis_a^2) along axis a.
  const Vec3 reach = radius_ * (Vec3::Ones() - axis_.cwiseAbs2()).cwiseMax(0.0).cwiseSqrt();
  const Vec3 top = bottom_ + length_ * axis_;
  Bounds<3> b;
  b.lower = bottom_.cwiseMin(top) - reach;
  b.upper = bottom_.cwiseMax(top) + reach;
  return b;
}

std::string Cylinder::surfaceName(const Vec3& x) const {
  switch (activePart(frame(x))) {
    case Part::Bottom:
      return qualifiedSurfaceName(name_, "bottom");
    case Part::Top:
      return qualifiedSurfaceName(name_, "top");
    case Part::Side:
      break;
  }
  return qualifiedSurfaceName(name_, "side");
}

}  // namespace mfwave
