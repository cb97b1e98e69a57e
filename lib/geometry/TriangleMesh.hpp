#pragma once
// A 3-D solid bounded by a closed triangle surface mesh (vertices and triangles of vertex indices),
// e.g. read from an STL file by geometry_vtk's readSurfaceMesh. Its one surface is "surface".
//
// The distance is to the nearest triangle (through a TriangleTree). Inside is decided by the parity
// of the triangles a ray from x crosses, which is robust as long as no crossing lands on an edge or
// a vertex and the ray does not graze a triangle: such a ray is set aside and the next of a fixed
// set of skew directions tried; should all of them be ambiguous, the generalised winding number
// (the solid angle the surface subtends at x over 4 pi) decides.
//
// Refused at construction: an open mesh (says how many boundary edges), edges of more than two
// triangles, inconsistent orientation, degenerate triangles. A consistently inward-oriented mesh
// (negative enclosed volume) is turned outward. Self-intersections are not looked for.

#include "geometry/Solid.hpp"
#include "geometry/TriangleTree.hpp"

#include <array>
#include <string>
#include <vector>

namespace mfwave {

class TriangleMesh final : public Solid<3> {
 public:
  // Throws InputError("<name or mesh>.triangles") for the defects above, ".vertices" for a vertex
  // that is not finite.
  TriangleMesh(std::vector<Vec3> vertices, std::vector<std::array<Index, 3>> triangles, const std::string& name = "");

  // Points within 1e-12 of the mesh's diagonal of a triangle count as on the surface (distance 0).
  Real signedDistance(const Vec3& x) const override;
  // The unit normal of the nearest triangle.
  Vec3 normal(const Vec3& x) const override;
  Bounds<3> bounds() const override { return bounds_; }
  std::string surfaceName(const Vec3& x) const override;

  const std::vector<Vec3>& vertices() const { return vertices_; }
  // Outward oriented (possibly reordered from the input).
  const std::vector<std::array<Index, 3>>& triangles() const { return triangles_; }
  Real volume() const { return volume_; }
  Real area() const { return area_; }
  // Strictly inside by ray parity (winding number as the last resort); either answer on the surface.
  bool encloses(const Vec3& x) const;
  // Generalised winding number at x: 1 inside, 0 outside (to rounding), 1/2 on a face.
  Real windingNumber(const Vec3& x) const;

 private:
  // +1 or -1 when the ray from x along `direction` crosses the surface an odd or even number of
  // times with every crossing well inside a triangle, 0 when one is ambiguous.
  int rayParity(const Vec3& x, const Vec3& direction) const;

  std::string name_;
  std::vector<Vec3> vertices_;
  std::vector<std::array<Index, 3>> triangles_;
  std::vector<Vec3> normals_;
  TriangleTree tree_;
  Bounds<3> bounds_;
  Real volume_ = 0;
  Real area_ = 0;
  Real onSurface_ = 0;
};

}  // namespace mfwave
