#pragma once
// A 2-D solid bounded by a simple polygon (PlanarPolygon: vertices in order, either orientation).
// Edge i, from vertex i to vertex i + 1, is the surface "edge<i>".

#include "geometry/PlanarPolygon.hpp"
#include "geometry/Solid.hpp"

#include <string>
#include <vector>

namespace mfwave {

class Polygon final : public Solid<2> {
 public:
  // Throws InputError("<name or polygon>.vertices") for fewer than 3 vertices, coinciding
  // neighbours, or edges that cross, touch or overlap.
  explicit Polygon(std::vector<Vec2> vertices, const std::string& name = "");

  Real signedDistance(const Vec2& x) const override { return shape_.signedDistance(x); }
  Vec2 normal(const Vec2& x) const override { return shape_.outwardNormal(shape_.nearestEdge(x).edge); }
  Bounds<2> bounds() const override { return shape_.bounds(); }
  std::string surfaceName(const Vec2& x) const override;

  const PlanarPolygon& shape() const { return shape_; }

 private:
  std::string name_;
  PlanarPolygon shape_;
};

}  // namespace mfwave
