#include "geometry/TriangleTree.hpp"

#include "core/Error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace mfwave {
namespace {

constexpr std::int32_t kLeafTriangles = 4;

// Closest point to p on the segment a-b.
Vec3 treeClosestOnSegment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 e = b - a;
  const Real t = std::clamp((p - a).dot(e) / e.squaredNorm(), 0.0, 1.0);
  return a + t * e;
}

// Closest point to p on the triangle a, b, c: the projection onto its plane when that falls
// inside (all barycentric weights >= 0), else the closest point on the nearest side.
Vec3 treeClosestOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 n = (b - a).cross(c - a);
  const Real nn = n.squaredNorm();
  const Vec3 q = p - ((p - a).dot(n) / nn) * n;
  const Real wa = (b - q).cross(c - q).dot(n);
  const Real wb = (c - q).cross(a - q).dot(n);
  const Real wc = nn - wa - wb;
  if (wa >= 0 && wb >= 0 && wc >= 0) return q;
  Vec3 best = treeClosestOnSegment(p, a, b);
  for (const Vec3& candidate : {treeClosestOnSegment(p, b, c), treeClosestOnSegment(p, c, a)})
    if ((candidate - p).squaredNorm() < (best - p).squaredNorm()) best = candidate;
  return best;
}

Real treeBoxSquaredDistance(const Vec3& x, const Vec3& lower, const Vec3& upper) {
  return (lower - x).cwiseMax(x - upper).cwiseMax(0.0).squaredNorm();
}

}  // namespace

TriangleTree::TriangleTree(const std::vector<Vec3>& vertices, const std::vector<std::array<Index, 3>>& triangles) {
  if (triangles.size() > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max() / 4))
    throw Error("TriangleTree: too many triangles (" + std::to_string(triangles.size()) + ")");
  const auto count = static_cast<std::int32_t>(triangles.size());
  std::vector<Vec3> centroids, lowers, uppers;
  centroids.reserve(triangles.size());
  lowers.reserve(triangles.size());
  uppers.reserve(triangles.size());
  for (const std::array<Index, 3>& t : triangles) {
    const Vec3& a = vertices[static_cast<std::size_t>(t[0])];
    const Vec3& b = vertices[static_cast<std::size_t>(t[1])];
    const Vec3& c = vertices[static_cast<std::size_t>(t[2])];
    centroids.push_back((a + b + c) / 3.0);
    lowers.push_back(a.cwiseMin(b).cwiseMin(c));
    uppers.push_back(a.cwiseMax(b).cwiseMax(c));
  }
  std::vector<std::int32_t> order(triangles.size());
  std::iota(order.begin(), order.end(), 0);
  nodes_.reserve(2 * triangles.size() / kLeafTriangles + 2);
  if (count > 0) build(order, 0, count, centroids, lowers, uppers);

  corners_.reserve(3 * triangles.size());
  triangleIndex_.reserve(triangles.size());
  for (const std::int32_t t : order) {
    const std::array<Index, 3>& tri = triangles[static_cast<std::size_t>(t)];
    for (const Index v : tri) corners_.push_back(vertices[static_cast<std::size_t>(v)]);
    triangleIndex_.push_back(t);
  }
}

std::int32_t TriangleTree::build(std::vector<std::int32_t>& order, std::int32_t begin, std::int32_t end,
                                 const std::vector<Vec3>& centroids, const std::vector<Vec3>& lowers,
                                 const std::vector<Vec3>& uppers) {
  const auto self = static_cast<std::int32_t>(nodes_.size());
  Node node{Vec3::Constant(std::numeric_limits<Real>::infinity()),
            Vec3::Constant(-std::numeric_limits<Real>::infinity()), begin, end - begin};
  Vec3 centreLow = node.lower, centreHigh = node.upper;
  for (std::int32_t k = begin; k < end; ++k) {
    const auto t = static_cast<std::size_t>(order[static_cast<std::size_t>(k)]);
    node.lower = node.lower.cwiseMin(lowers[t]);
    node.upper = node.upper.cwiseMax(uppers[t]);
    centreLow = centreLow.cwiseMin(centroids[t]);
    centreHigh = centreHigh.cwiseMax(centroids[t]);
  }
  nodes_.push_back(node);
  if (end - begin <= kLeafTriangles) return self;

  int axis = 0;
  (centreHigh - centreLow).maxCoeff(&axis);
  const std::int32_t middle = begin + (end - begin) / 2;
  std::nth_element(order.begin() + begin, order.begin() + middle, order.begin() + end,
                   [&](std::int32_t p, std::int32_t q) {
                     return centroids[static_cast<std::size_t>(p)][axis] < centroids[static_cast<std::size_t>(q)][axis];
                   });
  build(order, begin, middle, centroids, lowers, uppers);  // the first child follows its parent
  const std::int32_t second = build(order, middle, end, centroids, lowers, uppers);
  nodes_[static_cast<std::size_t>(self)].first = second;
  nodes_[static_cast<std::size_t>(self)].count = 0;
  return self;
}

TriangleTree::Nearest TriangleTree::nearest(const Vec3& x) const {
  Nearest best;
  best.squaredDistance = std::numeric_limits<Real>::infinity();
  Real bestPlane = -1;
  if (nodes_.empty()) return best;
  std::int32_t stack[64];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[static_cast<std::size_t>(stack[--top])];
    // Rounding makes triangles sharing an edge differ in the last bits: within `tie` they are as near.
    const Real tie = 1e-12 * best.squaredDistance;
    if (treeBoxSquaredDistance(x, node.lower, node.upper) > best.squaredDistance + tie) continue;
    if (node.count > 0) {
      for (std::int32_t k = node.first; k < node.first + node.count; ++k) {
        const auto s = static_cast<std::size_t>(k);
        const Vec3& a = corners_[3 * s];
        const Vec3& b = corners_[3 * s + 1];
        const Vec3& c = corners_[3 * s + 2];
        const Real squared = (treeClosestOnTriangle(x, a, b, c) - x).squaredNorm();
        const Real within = 1e-12 * std::min(squared, best.squaredDistance);
        if (squared > best.squaredDistance + within) continue;
        const Real plane = std::abs((x - a).dot((b - a).cross(c - a).normalized()));
        if (squared < best.squaredDistance - within || plane > bestPlane) {
          best.triangle = triangleIndex_[s];
          best.squaredDistance = squared;
          bestPlane = plane;
        }
      }
      continue;
    }
    // Visit the nearer child first, so the bound tightens early.
    const std::int32_t self = static_cast<std::int32_t>(&node - nodes_.data());
    const Node& left = nodes_[static_cast<std::size_t>(self + 1)];
    const Node& right = nodes_[static_cast<std::size_t>(node.first)];
    const bool leftFirst =
        treeBoxSquaredDistance(x, left.lower, left.upper) <= treeBoxSquaredDistance(x, right.lower, right.upper);
    stack[top++] = leftFirst ? node.first : self + 1;
    stack[top++] = leftFirst ? self + 1 : node.first;
  }
  return best;
}

bool TriangleTree::rayMeetsBox(const Node& node, const Vec3& origin, const Vec3& inverse) const {
  Real enter = 0, leave = std::numeric_limits<Real>::infinity();
  for (int a = 0; a < 3; ++a) {
    Real t0 = (node.lower[a] - origin[a]) * inverse[a];
    Real t1 = (node.upper[a] - origin[a]) * inverse[a];
    if (t0 > t1) std::swap(t0, t1);
    enter = std::max(enter, t0);
    leave = std::min(leave, t1);
  }
  return enter <= leave;
}

}  // namespace mfwave
