#pragma once
// Test helper: closed triangle meshes with known volumes, outward oriented: a box and an
// icosphere (an icosahedron whose faces are split in four `levels` times, new points pushed out
// to the sphere).

#include "core/Types.hpp"

#include <Eigen/Geometry>  // cross products

#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

namespace mfwave::testing {

struct MeshShape {
  std::vector<Vec3> vertices;
  std::vector<std::array<Index, 3>> triangles;
};

// The box [lower, upper] as 12 triangles, two per face.
inline MeshShape boxMesh(const Vec3& lower, const Vec3& upper) {
  MeshShape m;
  for (int k = 0; k < 8; ++k)
    m.vertices.emplace_back((k & 1) ? upper.x() : lower.x(), (k & 2) ? upper.y() : lower.y(),
                            (k & 4) ? upper.z() : lower.z());
  // Corners of each face, counter-clockwise seen from outside.
  const int faces[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  for (const auto& f : faces) {
    m.triangles.push_back({f[0], f[1], f[2]});
    m.triangles.push_back({f[0], f[2], f[3]});
  }
  return m;
}

inline MeshShape icosphereMesh(const Vec3& centre, Real radius, int levels) {
  const Real g = (1 + std::sqrt(5.0)) / 2;
  std::vector<Vec3> unit = {Vec3(-1, g, 0), Vec3(1, g, 0), Vec3(-1, -g, 0), Vec3(1, -g, 0),
                            Vec3(0, -1, g), Vec3(0, 1, g), Vec3(0, -1, -g), Vec3(0, 1, -g),
                            Vec3(g, 0, -1), Vec3(g, 0, 1), Vec3(-g, 0, -1), Vec3(-g, 0, 1)};
  for (Vec3& v : unit) v.normalize();
  std::vector<std::array<Index, 3>> tris = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                            {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                            {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                            {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<Index, Index>, Index> middle;
    const auto midpoint = [&](Index a, Index b) {
      const std::pair<Index, Index> key(std::min(a, b), std::max(a, b));
      const auto found = middle.find(key);
      if (found != middle.end()) return found->second;
      unit.push_back((unit[static_cast<std::size_t>(a)] + unit[static_cast<std::size_t>(b)]).normalized());
      const Index id = static_cast<Index>(unit.size()) - 1;
      middle.emplace(key, id);
      return id;
    };
    std::vector<std::array<Index, 3>> finer;
    for (const auto& t : tris) {
      const Index ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]), ca = midpoint(t[2], t[0]);
      finer.push_back({t[0], ab, ca});
      finer.push_back({t[1], bc, ab});
      finer.push_back({t[2], ca, bc});
      finer.push_back({ab, bc, ca});
    }
    tris = std::move(finer);
  }
  MeshShape m;
  for (const Vec3& v : unit) m.vertices.push_back(centre + radius * v);
  m.triangles = std::move(tris);
  return m;
}

// Volume enclosed by an outward-oriented closed mesh (divergence theorem).
inline Real meshShapeVolume(const MeshShape& m) {
  Real six = 0;
  for (const auto& t : m.triangles)
    six += m.vertices[static_cast<std::size_t>(t[0])].dot(
        m.vertices[static_cast<std::size_t>(t[1])].cross(m.vertices[static_cast<std::size_t>(t[2])]));
  return six / 6;
}

}  // namespace mfwave::testing
