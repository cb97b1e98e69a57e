#pragma once
// A simple polygon in the plane, checked once and queried many times: the shape a 2-D polygon
// solid, an extruded polygon and a planar 3-D crack share. Vertices are given in order, either
// orientation; edge i runs from vertex i to vertex i + 1 (the last back to the first). Outward
// normals account for the orientation, so a clockwise list describes the same solid.

#include "core/Types.hpp"
#include "geometry/Bounds.hpp"

#include <string>
#include <vector>

namespace mfwave {

class PlanarPolygon {
 public:
  // Throws InputError(key) for fewer than 3 vertices, a vertex that is not finite, two
  // consecutive vertices that coincide, two edges that cross, touch or overlap (naming them).
  // Checking every pair of edges costs O(n^2), fine for the hundreds of vertices a scene writes.
  PlanarPolygon(std::vector<Vec2> vertices, const std::string& key);

  Index size() const { return static_cast<Index>(vertices_.size()); }
  const Vec2& vertex(Index i) const { return vertices_[static_cast<std::size_t>(i)]; }
  // Enclosed area (positive whatever the orientation).
  Real area() const { return area_; }
  bool counterClockwise() const { return counterClockwise_; }
  // Unit normal of edge i pointing out of the polygon.
  const Vec2& outwardNormal(Index edge) const { return normals_[static_cast<std::size_t>(edge)]; }

  struct NearestEdge {
    Index edge;
    Real distance;
  };
  // The edge nearest x. When several are as near (x nearest a vertex), the one whose line is
  // farthest from x: at a convex corner, the edge x lies further out of (as a box picks its face).
  NearestEdge nearestEdge(const Vec2& x) const;
  // Strictly inside by the crossing number (either answer for a point on an edge).
  bool contains(const Vec2& x) const;
  // Exact: distance to the nearest edge, negative inside.
  Real signedDistance(const Vec2& x) const;
  Bounds<2> bounds() const;

 private:
  std::vector<Vec2> vertices_;
  std::vector<Vec2> normals_;
  Real area_ = 0;
  bool counterClockwise_ = true;
};

}  // namespace mfwave
