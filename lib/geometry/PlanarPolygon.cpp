#include "geometry/PlanarPolygon.hpp"

#include "core/Error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace mfwave {
namespace {

// Twice the signed area of the triangle a, b, c: positive when c is left of a -> b.
Real polygonOrient(const Vec2& a, const Vec2& b, const Vec2& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

// c, known to be on the line through a and b, lies within the segment's box.
bool polygonWithinSegment(const Vec2& a, const Vec2& b, const Vec2& c) {
  return c.x() >= std::min(a.x(), b.x()) && c.x() <= std::max(a.x(), b.x()) && c.y() >= std::min(a.y(), b.y()) &&
         c.y() <= std::max(a.y(), b.y());
}

// The closed segments a-b and c-d share a point (crossing, touching or overlapping).
bool polygonSegmentsMeet(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const Real o1 = polygonOrient(a, b, c), o2 = polygonOrient(a, b, d);
  const Real o3 = polygonOrient(c, d, a), o4 = polygonOrient(c, d, b);
  if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0))) return true;
  return (o1 == 0 && polygonWithinSegment(a, b, c)) || (o2 == 0 && polygonWithinSegment(a, b, d)) ||
         (o3 == 0 && polygonWithinSegment(c, d, a)) || (o4 == 0 && polygonWithinSegment(c, d, b));
}

std::string polygonEdgeText(std::size_t i) { return "edge" + std::to_string(i); }

}  // namespace

PlanarPolygon::PlanarPolygon(std::vector<Vec2> vertices, const std::string& key) : vertices_(std::move(vertices)) {
  const std::size_t n = vertices_.size();
  if (n < 3) throw InputError(key, "a polygon needs at least 3 vertices, got " + std::to_string(n));
  for (std::size_t i = 0; i < n; ++i)
    if (!vertices_[i].allFinite()) throw InputError(key, "vertex " + std::to_string(i) + " is not finite");
  for (std::size_t i = 0; i < n; ++i)
    if (vertices_[i] == vertices_[(i + 1) % n])
      throw InputError(key, "vertices " + std::to_string(i) + " and " + std::to_string((i + 1) % n) +
                                " coincide: " + polygonEdgeText(i) + " has no length");

  // Simple: edges that share a vertex may not fold back onto each other, other pairs may not meet.
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& a = vertices_[i];
    const Vec2& b = vertices_[(i + 1) % n];
    for (std::size_t j = i + 1; j < n; ++j) {
      const Vec2& c = vertices_[j];
      const Vec2& d = vertices_[(j + 1) % n];
      const bool next = j == i + 1;
      const bool wrap = i == 0 && j == n - 1;
      if (next || wrap) {
        // Shared vertex s, the edges' other ends p and q: overlapping when p and q lie on one ray from s.
        const Vec2& s = next ? b : a;
        const Vec2& p = next ? a : b;
        const Vec2& q = next ? d : c;
        if (polygonOrient(s, p, q) == 0 && (p - s).dot(q - s) > 0)
          throw InputError(key, "the polygon is self-intersecting: " + polygonEdgeText(i) + " and " + polygonEdgeText(j) +
                                    " fold back onto each other");
        continue;
      }
      if (std::max(a.x(), b.x()) < std::min(c.x(), d.x()) || std::max(c.x(), d.x()) < std::min(a.x(), b.x()) ||
          std::max(a.y(), b.y()) < std::min(c.y(), d.y()) || std::max(c.y(), d.y()) < std::min(a.y(), b.y()))
        continue;
      if (polygonSegmentsMeet(a, b, c, d))
        throw InputError(key, "the polygon is self-intersecting: " + polygonEdgeText(i) + " and " + polygonEdgeText(j) + " meet");
    }
  }

  Real twiceArea = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& a = vertices_[i];
    const Vec2& b = vertices_[(i + 1) % n];
    twiceArea += a.x() * b.y() - b.x() * a.y();
  }
  if (!(std::abs(twiceArea) > 0)) throw InputError(key, "the polygon encloses no area");
  counterClockwise_ = twiceArea > 0;
  area_ = 0.5 * std::abs(twiceArea);

  normals_.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 e = vertices_[(i + 1) % n] - vertices_[i];
    const Vec2 right(e.y(), -e.x());  // outward for a counter-clockwise polygon
    normals_.push_back((counterClockwise_ ? right : Vec2(-right)) / e.norm());
  }
}

PlanarPolygon::NearestEdge PlanarPolygon::nearestEdge(const Vec2& x) const {
  const std::size_t n = vertices_.size();
  // Squared distance from x to edge i, and x's distance from the edge's line.
  const auto measure = [&](std::size_t i, Real& squared, Real& line) {
    const Vec2& a = vertices_[i];
    const Vec2 e = vertices_[(i + 1) % n] - a;
    const Vec2 offset = x - a;
    const Real t = std::clamp(offset.dot(e) / e.squaredNorm(), 0.0, 1.0);
    squared = (offset - t * e).squaredNorm();
    line = std::abs(offset.dot(normals_[i]));
  };
  std::size_t best = 0;
  Real bestSquared = 0, bestLine = 0;
  measure(0, bestSquared, bestLine);
  for (std::size_t i = 1; i < n; ++i) {
    Real squared = 0, line = 0;
    measure(i, squared, line);
    // Rounding makes the two edges at a vertex differ in the last bits: closer by more than that
    // wins, within it the edge whose line is farther.
    const Real tie = 1e-12 * std::max(squared, bestSquared);
    if (squared < bestSquared - tie || (squared <= bestSquared + tie && line > bestLine)) {
      best = i;
      bestSquared = squared;
      bestLine = line;
    }
  }
  return {static_cast<Index>(best), std::sqrt(bestSquared)};
}

bool PlanarPolygon::contains(const Vec2& x) const {
  const std::size_t n = vertices_.size();
  bool inside = false;
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const Vec2& a = vertices_[i];
    const Vec2& b = vertices_[j];
    if ((a.y() > x.y()) != (b.y() > x.y())) {
      const Real crossing = a.x() + (x.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
      if (x.x() < crossing) inside = !inside;
    }
  }
  return inside;
}

Real PlanarPolygon::signedDistance(const Vec2& x) const {
  const Real d = nearestEdge(x).distance;
  return contains(x) ? -d : d;
}

Bounds<2> PlanarPolygon::bounds() const {
  Bounds<2> b;
  for (const Vec2& v : vertices_) {
    b.lower = b.lower.cwiseMin(v);
    b.upper = b.upper.cwiseMax(v);
  }
  return b;
}

}  // namespace mfwave
