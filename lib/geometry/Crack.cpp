#include "geometry/Crack.hpp"

#include "core/Error.hpp"

#include <Eigen/Geometry>  // cross products

#include <algorithm>
#include <cmath>
#include <string>

namespace mfwave {
namespace {

// Twice the signed area of a, b, c: which side of the line a -> b the point c is on.
Real crackOrient(const Vec2& a, const Vec2& b, const Vec2& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

}  // namespace

Crack<2>::Crack(const Vec2& start, const Vec2& end) : start_(start), end_(end) {
  if (!start.allFinite() || !end.allFinite()) throw InputError("crack", "the end points must be finite");
  if (start == end) throw InputError("crack", "the end points coincide: a crack needs a length");
  bounds_.lower = start.cwiseMin(end);
  bounds_.upper = start.cwiseMax(end);
}

bool Crack<2>::crosses(const Vec2& a, const Vec2& b) const {
  const bool sideA = crackOrient(start_, end_, a) >= 0;
  const bool sideB = crackOrient(start_, end_, b) >= 0;
  if (sideA == sideB) return false;
  // a and b are apart across the crack's line; the crack must reach the line through a and b.
  const Real s = crackOrient(a, b, start_), e = crackOrient(a, b, end_);
  return (s <= 0 && e >= 0) || (s >= 0 && e <= 0);
}

Crack<3>::Frame Crack<3>::frameOf(const std::vector<Vec3>& points) {
  if (points.size() < 3) throw InputError("crack", "a 3-D crack needs at least 3 points, got " + std::to_string(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!points[i].allFinite()) throw InputError("crack", "point " + std::to_string(i) + " is not finite");
  // Newell's normal: the vector area of the polygon, sound for non-convex polygons too.
  Vec3 area = Vec3::Zero();
  for (std::size_t i = 0; i < points.size(); ++i) area += points[i].cross(points[(i + 1) % points.size()]);
  Real size = 0;
  for (const Vec3& p : points) size = std::max(size, (p - points.front()).norm());
  if (!(area.norm() > 1e-12 * size * size)) throw InputError("crack", "the points enclose no area");
  Frame f;
  f.origin = points.front();
  f.normal = area.normalized();
  for (std::size_t i = 0; i < points.size(); ++i)
    if (std::abs(f.normal.dot(points[i] - f.origin)) > 1e-9 * size)
      throw InputError("crack", "point " + std::to_string(i) + " is off the plane of the others: a crack must be planar");
  const Vec3 across = std::abs(f.normal.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  f.u = (across - across.dot(f.normal) * f.normal).normalized();
  f.v = f.normal.cross(f.u);
  return f;
}

PlanarPolygon Crack<3>::inPlane(const std::vector<Vec3>& points, const Vec3& origin, const Vec3& u, const Vec3& v) {
  std::vector<Vec2> flat;
  flat.reserve(points.size());
  for (const Vec3& p : points) flat.emplace_back(u.dot(p - origin), v.dot(p - origin));
  return PlanarPolygon(std::move(flat), "crack");
}

Crack<3>::Crack(const std::vector<Vec3>& points) : Crack(points, frameOf(points)) {}

Crack<3>::Crack(const std::vector<Vec3>& points, const Frame& frame)
    : origin_(frame.origin),
      normal_(frame.normal),
      u_(frame.u),
      v_(frame.v),
      shape_(inPlane(points, frame.origin, frame.u, frame.v)),
      tolerance_(0) {
  for (const Vec3& p : points) {
    bounds_.lower = bounds_.lower.cwiseMin(p);
    bounds_.upper = bounds_.upper.cwiseMax(p);
  }
  tolerance_ = 1e-12 * (bounds_.upper - bounds_.lower).norm();
}

Crack<3> Crack<3>::rectangle(const Vec3& corner, const Vec3& edge1, const Vec3& edge2) {
  if (!(edge1.cross(edge2).norm() > 1e-12 * edge1.norm() * edge2.norm()) || !(edge1.norm() > 0) || !(edge2.norm() > 0))
    throw InputError("crack", "the rectangle's edges must be non-zero and not parallel");
  return Crack({corner, corner + edge1, corner + edge1 + edge2, corner + edge2});
}

bool Crack<3>::crosses(const Vec3& a, const Vec3& b) const {
  const Real sa = normal_.dot(a - origin_), sb = normal_.dot(b - origin_);
  if ((sa >= 0) == (sb >= 0)) return false;
  const Vec3 hit = a + (sa / (sa - sb)) * (b - a);
  const Vec2 flat(u_.dot(hit - origin_), v_.dot(hit - origin_));
  return shape_.signedDistance(flat) <= tolerance_;
}

}  // namespace mfwave
