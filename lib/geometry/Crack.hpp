#pragma once
// A crack: a surface of zero thickness inside a solid across which material does not interact (a
// segment in 2-D, a planar polygon in 3-D). Particle methods cut a pair interaction when the
// straight segment between the two particles crosses a crack (the visibility criterion), which is
// what crosses(a, b) answers.
//
// Each side of the crack's line or plane is half-open: a point exactly on it belongs to the side its
// normal points to. So a particle placed on a crack (lattice nodes can lie on one) still sits on
// exactly one side, and the crack separates it from the particles across; the crack's own edges
// and tips are part of it (a segment through a tip is cut).

#include "core/Types.hpp"
#include "geometry/Bounds.hpp"
#include "geometry/PlanarPolygon.hpp"

#include <vector>

namespace mfwave {

template <int D>
class Crack;

// A 2-D crack: the segment from `start` to `end`.
template <>
class Crack<2> {
 public:
  // Throws InputError("crack") when an end point is not finite or the two coincide.
  Crack(const Vec2& start, const Vec2& end);
  // The closed segment a-b reaches from one side of the crack to the other through it.
  bool crosses(const Vec2& a, const Vec2& b) const;
  const Bounds<2>& bounds() const { return bounds_; }

 private:
  Vec2 start_;
  Vec2 end_;
  Bounds<2> bounds_;
};

// A 3-D crack: a planar simple polygon (points in order, coplanar).
template <>
class Crack<3> {
 public:
  // Throws InputError("crack") for fewer than 3 points, points that are not coplanar (farther than
  // 1e-9 of the polygon's size from its plane), or a polygon that is not simple in its plane.
  explicit Crack(const std::vector<Vec3>& points);
  // The rectangle corner, corner + edge1, corner + edge1 + edge2, corner + edge2; throws
  // InputError("crack") when the edges are parallel or zero.
  static Crack rectangle(const Vec3& corner, const Vec3& edge1, const Vec3& edge2);

  bool crosses(const Vec3& a, const Vec3& b) const;
  const Bounds<3>& bounds() const { return bounds_; }
  const Vec3& normal() const { return normal_; }

 private:
  // The crack's plane: a point on it, its unit normal and two in-plane unit axes.
  struct Frame {
    Vec3 origin, normal, u, v;
  };
  static Frame frameOf(const std::vector<Vec3>& points);
  Crack(const std::vector<Vec3>& points, const Frame& frame);
  // The points in the plane's (u, v) coordinates about its origin.
  static PlanarPolygon inPlane(const std::vector<Vec3>& points, const Vec3& origin, const Vec3& u, const Vec3& v);

  Vec3 origin_;
  Vec3 normal_;
  Vec3 u_;  // in-plane axes, with normal_ a right-handed frame
  Vec3 v_;
  PlanarPolygon shape_;  // in (u, v) coordinates about origin_
  Real tolerance_;       // how far outside its edges a crossing still counts as on the crack
  Bounds<3> bounds_;
};

}  // namespace mfwave
