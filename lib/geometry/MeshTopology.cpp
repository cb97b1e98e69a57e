#include "geometry/MeshTopology.hpp"

#include "core/Error.hpp"

#include <algorithm>
#include <string>
#include <tuple>

namespace mfwave {
namespace {

// One side of a triangle, stored with its end points sorted so both triangles of an edge sort
// together; `forward` remembers whether the triangle runs low -> high.
struct MeshEdgeUse {
  Index low;
  Index high;
  bool forward;
};

}  // namespace

void checkClosedOrientedSurface(Index vertexCount, const std::vector<std::array<Index, 3>>& triangles,
                                const std::string& key) {
  if (triangles.empty()) throw InputError(key, "the mesh has no triangles");
  std::vector<MeshEdgeUse> uses;
  uses.reserve(3 * triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const std::array<Index, 3>& tri = triangles[t];
    for (const Index v : tri)
      if (v < 0 || v >= vertexCount)
        throw InputError(key, "triangle " + std::to_string(t) + " names vertex " + std::to_string(v) + ", outside [0, " +
                                  std::to_string(vertexCount) + ")");
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[2] == tri[0])
      throw InputError(key, "triangle " + std::to_string(t) + " repeats a vertex");
    for (std::size_t k = 0; k < 3; ++k) {
      const Index a = tri[k], b = tri[(k + 1) % 3];
      uses.push_back({std::min(a, b), std::max(a, b), a < b});
    }
  }
  std::sort(uses.begin(), uses.end(), [](const MeshEdgeUse& p, const MeshEdgeUse& q) {
    return std::tie(p.low, p.high) < std::tie(q.low, q.high);
  });

  Index boundary = 0, crowded = 0, misoriented = 0;
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i + 1;
    while (j < uses.size() && uses[j].low == uses[i].low && uses[j].high == uses[i].high) ++j;
    const std::size_t count = j - i;
    if (count == 1) ++boundary;
    if (count > 2) ++crowded;
    if (count == 2 && uses[i].forward == uses[i + 1].forward) ++misoriented;
    i = j;
  }
  if (boundary > 0)
    throw InputError(key, "the mesh is open: " + std::to_string(boundary) +
                              " boundary edges (edges of only one triangle); a solid needs a closed surface, every edge "
                              "shared by exactly two triangles");
  if (crowded > 0)
    throw InputError(key, std::to_string(crowded) +
                              " edges are shared by more than two triangles; a solid needs every edge shared by exactly two");
  if (misoriented > 0)
    throw InputError(key, "the triangles are not consistently oriented: " + std::to_string(misoriented) +
                              " edges are traversed the same way by both their triangles");
}

}  // namespace mfwave
