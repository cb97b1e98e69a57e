#include "geometry/TriangleMesh.hpp"

#include "core/Error.hpp"
#include "geometry/MeshTopology.hpp"
#include "geometry/SolidName.hpp"

#include <cmath>
#include <string>

namespace mfwave {
namespace {

// Skew directions: no component zero (the tree's slab test divides by them) and none near a
// lattice or coordinate direction, along which triangles of machined parts tend to line up.
const Vec3 kParityDirections[] = {
    Vec3(0.5387, 0.3136, 0.7819),  Vec3(-0.6121, 0.7312, 0.2657), Vec3(0.2893, -0.5527, 0.7814),
    Vec3(-0.4406, -0.3789, -0.8139), Vec3(0.8318, 0.1927, -0.5205), Vec3(-0.1543, 0.9247, -0.3481),
    Vec3(0.7071, -0.6703, 0.2253),
};

// Barycentric margin below which a crossing is too near an edge to count safely.
constexpr Real kEdgeMargin = 1e-9;

}  // namespace

TriangleMesh::TriangleMesh(std::vector<Vec3> vertices, std::vector<std::array<Index, 3>> triangles,
                           const std::string& name)
    : name_(checkedSolidName(name, "mesh")), vertices_(std::move(vertices)), triangles_(std::move(triangles)) {
  const std::string key = solidKey(name_, "mesh", "triangles");
  for (std::size_t i = 0; i < vertices_.size(); ++i)
    if (!vertices_[i].allFinite())
      throw InputError(solidKey(name_, "mesh", "vertices"), "vertex " + std::to_string(i) + " is not finite");
  checkClosedOrientedSurface(static_cast<Index>(vertices_.size()), triangles_, key);

  for (const Vec3& v : vertices_) {
    bounds_.lower = bounds_.lower.cwiseMin(v);
    bounds_.upper = bounds_.upper.cwiseMax(v);
  }
  const Real diagonal = (bounds_.upper - bounds_.lower).norm();
  onSurface_ = 1e-12 * diagonal;

  // Enclosed volume by the divergence theorem (a sum of tetrahedra from the origin taken about the
  // box centre, which keeps the terms small); its sign says whether the normals point out.
  const Vec3 centre = 0.5 * (bounds_.lower + bounds_.upper);
  Real sixVolume = 0;
  for (std::size_t t = 0; t < triangles_.size(); ++t) {
    const Vec3 a = vertices_[static_cast<std::size_t>(triangles_[t][0])] - centre;
    const Vec3 b = vertices_[static_cast<std::size_t>(triangles_[t][1])] - centre;
    const Vec3 c = vertices_[static_cast<std::size_t>(triangles_[t][2])] - centre;
    const Real twiceArea = (b - a).cross(c - a).norm();
    if (!(twiceArea > 1e-14 * diagonal * diagonal))
      throw InputError(key, "triangle " + std::to_string(t) + " is degenerate (no area)");
    area_ += 0.5 * twiceArea;
    sixVolume += a.dot(b.cross(c));
  }
  if (!(std::abs(sixVolume) > 1e-12 * diagonal * diagonal * diagonal))
    throw InputError(key, "the mesh encloses no volume");
  if (sixVolume < 0)
    for (std::array<Index, 3>& t : triangles_) std::swap(t[1], t[2]);
  volume_ = std::abs(sixVolume) / 6.0;

  normals_.reserve(triangles_.size());
  for (const std::array<Index, 3>& t : triangles_) {
    const Vec3& a = vertices_[static_cast<std::size_t>(t[0])];
    const Vec3& b = vertices_[static_cast<std::size_t>(t[1])];
    const Vec3& c = vertices_[static_cast<std::size_t>(t[2])];
    normals_.push_back((b - a).cross(c - a).normalized());
  }
  tree_ = TriangleTree(vertices_, triangles_);
}

int TriangleMesh::rayParity(const Vec3& x, const Vec3& direction) const {
  bool odd = false, ambiguous = false;
  tree_.alongRay(x, direction, [&](Index, const Vec3& a, const Vec3& b, const Vec3& c) {
    if (ambiguous) return;
    // Solve x + t direction = a + u (b - a) + v (c - a) by Cramer's rule.
    const Vec3 ab = b - a, ac = c - a;
    const Vec3 p = direction.cross(ac);
    const Real det = ab.dot(p);
    if (std::abs(det) <= 1e-12 * ab.norm() * ac.norm()) {
      // Parallel to the plane: it cannot cross, but a ray in the plane could run along the triangle.
      if (std::abs((x - a).dot(ab.cross(ac))) <= onSurface_ * ab.norm() * ac.norm()) ambiguous = true;
      return;
    }
    const Vec3 s = x - a;
    const Vec3 q = s.cross(ab);
    const Real u = s.dot(p) / det;
    const Real v = direction.dot(q) / det;
    const Real t = ac.dot(q) / det;
    if (u < -kEdgeMargin || v < -kEdgeMargin || u + v > 1 + kEdgeMargin || t <= 0) return;
    if (u < kEdgeMargin || v < kEdgeMargin || u + v > 1 - kEdgeMargin) {
      ambiguous = true;
      return;
    }
    odd = !odd;
  });
  if (ambiguous) return 0;
  return odd ? 1 : -1;
}

Real TriangleMesh::windingNumber(const Vec3& x) const {
  // Solid angle of each triangle seen from x (the tangent half-angle formula), summed.
  Real total = 0;
  for (const std::array<Index, 3>& t : triangles_) {
    const Vec3 a = vertices_[static_cast<std::size_t>(t[0])] - x;
    const Vec3 b = vertices_[static_cast<std::size_t>(t[1])] - x;
    const Vec3 c = vertices_[static_cast<std::size_t>(t[2])] - x;
    const Real la = a.norm(), lb = b.norm(), lc = c.norm();
    const Real numerator = a.dot(b.cross(c));
    const Real denominator = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
    total += 2 * std::atan2(numerator, denominator);
  }
  return total / (4 * kPi);
}

bool TriangleMesh::encloses(const Vec3& x) const {
  for (const Vec3& direction : kParityDirections) {
    const int parity = rayParity(x, direction.normalized());
    if (parity != 0) return parity > 0;
  }
  return windingNumber(x) > 0.5;
}

Real TriangleMesh::signedDistance(const Vec3& x) const {
  const Real distance = std::sqrt(tree_.nearest(x).squaredDistance);
  if (distance <= onSurface_) return 0;
  return encloses(x) ? -distance : distance;
}

Vec3 TriangleMesh::normal(const Vec3& x) const {
  return normals_[static_cast<std::size_t>(tree_.nearest(x).triangle)];
}

std::string TriangleMesh::surfaceName(const Vec3&) const {
  return qualifiedSurfaceName(name_, "surface");
}

}  // namespace mfwave
