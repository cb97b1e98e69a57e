#pragma once
// A bounding-volume hierarchy over triangles: the nearest triangle to a point and the triangles a
// ray may cross, in O(log n) each instead of a sweep over every triangle. A particle fill asks a
// mesh for thousands of distances per surface cell, so a linear sweep would dominate everything.
//
// Boxes are split at the median centroid along their longest side down to a few triangles per
// leaf; the corners of each triangle are copied in tree order, so a leaf reads contiguous memory.

#include "core/Types.hpp"

#include <Eigen/Geometry>  // cross products

#include <array>
#include <cstdint>
#include <vector>

namespace mfwave {

class TriangleTree {
 public:
  TriangleTree() = default;
  TriangleTree(const std::vector<Vec3>& vertices, const std::vector<std::array<Index, 3>>& triangles);

  struct Nearest {
    Index triangle = -1;  // index into the triangle list the tree was built from
    Real squaredDistance = 0;
  };
  // The triangle nearest x. When several are as near (x nearest an edge or a vertex they share),
  // the one whose plane is farthest from x, the face x lies most squarely in front of.
  Nearest nearest(const Vec3& x) const;

  // Calls visit(triangle, a, b, c) for every triangle in a leaf whose box the ray
  // origin + t * direction, t >= 0, meets (a superset of the triangles it crosses).
  template <class Visit>
  void alongRay(const Vec3& origin, const Vec3& direction, Visit&& visit) const;

 private:
  struct Node {
    Vec3 lower;
    Vec3 upper;
    std::int32_t first;  // leaf: first corner triple; inner node: index of the second child
    std::int32_t count;  // leaf: number of triangles; inner node: 0 (the first child follows)
  };
  std::int32_t build(std::vector<std::int32_t>& order, std::int32_t begin, std::int32_t end,
                     const std::vector<Vec3>& centroids, const std::vector<Vec3>& lowers,
                     const std::vector<Vec3>& uppers);
  bool rayMeetsBox(const Node& node, const Vec3& origin, const Vec3& inverse) const;

  std::vector<Node> nodes_;
  std::vector<Vec3> corners_;         // three per triangle, in tree order
  std::vector<Index> triangleIndex_;  // tree order -> original triangle
};

template <class Visit>
void TriangleTree::alongRay(const Vec3& origin, const Vec3& direction, Visit&& visit) const {
  if (nodes_.empty()) return;
  const Vec3 inverse = direction.cwiseInverse();
  std::int32_t stack[64];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[static_cast<std::size_t>(stack[--top])];
    if (!rayMeetsBox(node, origin, inverse)) continue;
    if (node.count > 0) {
      for (std::int32_t k = node.first; k < node.first + node.count; ++k) {
        const auto s = static_cast<std::size_t>(k);
        visit(triangleIndex_[s], corners_[3 * s], corners_[3 * s + 1], corners_[3 * s + 2]);
      }
    } else {
      const std::int32_t self = static_cast<std::int32_t>(&node - nodes_.data());
      stack[top++] = node.first;
      stack[top++] = self + 1;
    }
  }
}

}  // namespace mfwave
