#include "methods/collocation/SolidCollocationNodes.hpp"

#include "core/Error.hpp"
#include "particles/BoxFace.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <unordered_map>

namespace mfwave {

// A named namespace, not an anonymous one: the lambdas below capture its PointBuckets, and in a unity
// batch (MFWAVE_UNITY_LIBRARIES) a capture of an anonymous type is -Wsubobject-linkage.
namespace solid_nodes {

// Lattice counts per axis; dx must divide the box to 1e-9.
template <int D>
std::array<Index, D> cellCounts(const CollocationSolid<D>& solid, Real dx) {
  std::array<Index, D> n{};
  for (int a = 0; a < D; ++a) {
    const Real cells = (solid.upper[a] - solid.lower[a]) / dx;
    const Real whole = std::round(cells);
    if (!(dx > 0) || whole < 1 || std::abs(cells - whole) > 1e-9 * std::max<Real>(1, cells))
      throw InputError("geometry.spacing", "the spacing must divide the box along axis " + std::string(axisName(a)));
    n[static_cast<std::size_t>(a)] = static_cast<Index>(whole);
  }
  return n;
}

// Points of a lattice (counts per axis) in order, x fastest.
template <int D, class F>
void forEachPoint(const std::array<Index, D>& counts, F&& f) {
  Index total = 1;
  for (const Index c : counts) total *= c;
  std::array<Index, D> i{};
  for (Index k = 0; k < total; ++k) {
    Index rest = k;
    for (int a = 0; a < D; ++a) {
      i[static_cast<std::size_t>(a)] = rest % counts[static_cast<std::size_t>(a)];
      rest /= counts[static_cast<std::size_t>(a)];
    }
    f(i);
  }
}

// Points kept so far, bucketed by lattice cell, for the "no closer than" test.
template <int D>
class PointBuckets {
 public:
  PointBuckets(const Vec<D>& lower, Real size) : lower_(lower), size_(size) {}
  std::array<long, D> cellOf(const Vec<D>& x) const {
    std::array<long, D> c{};
    for (int a = 0; a < D; ++a) c[static_cast<std::size_t>(a)] = static_cast<long>(std::floor((x[a] - lower_[a]) / size_));
    return c;
  }
  // The distances to the points within one bucket of x farther than `beyond`, ascending.
  std::vector<Real> distances(const Vec<D>& x, Real beyond = -1) const {
    const std::array<long, D> c = cellOf(x);
    std::vector<Real> out;
    const int neighbours = D == 2 ? 9 : 27;
    for (int k = 0; k < neighbours; ++k) {
      std::array<long, D> b = c;
      int rest = k;
      for (int a = 0; a < D; ++a) {
        b[static_cast<std::size_t>(a)] += rest % 3 - 1;
        rest /= 3;
      }
      const auto it = buckets_.find(key(b));
      if (it == buckets_.end()) continue;
      for (const Vec<D>& y : it->second) {
        const Real r = (y - x).norm();
        if (r > beyond) out.push_back(r);
      }
    }
    std::sort(out.begin(), out.end());
    return out;
  }
  Real nearest(const Vec<D>& x) const {
    const std::vector<Real> d = distances(x);
    return d.empty() ? std::numeric_limits<Real>::infinity() : d.front();
  }
  void add(const Vec<D>& x) { buckets_[key(cellOf(x))].push_back(x); }

 private:
  static long key(const std::array<long, D>& c) {
    long k = 0;
    for (int a = D - 1; a >= 0; --a) k = k * 1000003L + c[static_cast<std::size_t>(a)];
    return k;
  }
  Vec<D> lower_;
  Real size_;
  std::unordered_map<long, std::vector<Vec<D>>> buckets_;
};

}  // namespace solid_nodes

template <int D>
SolidCollocationNodes<D> solidCollocationNodes(const CollocationSolid<D>& solid, Real dx, Real gap, Real minimum) {
  using solid_nodes::PointBuckets;
  using solid_nodes::cellCounts;
  using solid_nodes::forEachPoint;
  const std::array<Index, D> cells = cellCounts(solid, dx);
  std::array<Index, D> nodeCounts = cells;
  for (Index& c : nodeCounts) ++c;
  const Real tolerance = 1e-9 * dx;
  SolidCollocationNodes<D> out;
  std::vector<Vec<D>> interior, box, surface;
  std::vector<std::uint8_t> boxFaces;

  // lattice nodes: inside the box well inside the solid, or on the box's faces inside the solid
  forEachPoint<D>(nodeCounts, [&](const std::array<Index, D>& i) {
    Vec<D> x;
    std::uint8_t faces = 0;
    for (int a = 0; a < D; ++a) {
      const auto k = static_cast<std::size_t>(a);
      x[a] = i[k] == cells[k] ? solid.upper[a] : solid.lower[a] + dx * static_cast<Real>(i[k]);
      if (i[k] == 0) faces |= faceBit(2 * a);
      if (i[k] == cells[k]) faces |= faceBit(2 * a + 1);
    }
    const Real d = solid.distance(x);
    if (faces != 0 && d <= tolerance) {
      box.push_back(x);
      boxFaces.push_back(faces);
    } else if (faces == 0 && d <= -gap * dx) {
      interior.push_back(x);
    }
  });
  if (interior.empty())
    throw InputError("geometry.solid", "no lattice node lies inside the solid (at least half a spacing from its surface)");

  // surface points: the projections of the centres of the cells the surface may cut
  PointBuckets<D> kept(solid.lower, dx);
  const Real halfDiagonal = 0.5 * dx * std::sqrt(static_cast<Real>(D));
  forEachPoint<D>(cells, [&](const std::array<Index, D>& i) {
    Vec<D> x;
    for (int a = 0; a < D; ++a) x[a] = solid.lower[a] + dx * (static_cast<Real>(i[static_cast<std::size_t>(a)]) + 0.5);
    if (std::abs(solid.distance(x)) > halfDiagonal) return;
    for (int pass = 0; pass < 3; ++pass) x -= solid.distance(x) * solid.normal(x);
    if (std::abs(solid.distance(x)) > 1e-6 * dx) return;  // not on the surface (an edge the projection missed)
    for (int a = 0; a < D; ++a)
      if (x[a] < solid.lower[a] + gap * dx || x[a] > solid.upper[a] - gap * dx) return;  // the box's corner holds it
    if (kept.nearest(x) < minimum * dx) return;
    kept.add(x);
    surface.push_back(x);
  });

  for (const Vec<D>& x : interior) out.points.add(x, CollocationRowKind::Interior);
  for (std::size_t k = 0; k < box.size(); ++k) {
    const std::uint8_t faces = boxFaces[k];
    int face = -1;
    for (int f = 0; f < 2 * D; ++f)
      if (faces == faceBit(f)) face = f;  // on this face only
    if (face >= 0 && (solid.freeFaces & faceBit(face)) != 0)
      out.points.add(box[k], CollocationRowKind::Traction, faceNormal<D>(face));
    else
      out.points.add(box[k], CollocationRowKind::Displacement);
  }
  for (const Vec<D>& x : surface) {
    if (solid.clamped && solid.clamped(x))
      out.points.add(x, CollocationRowKind::Displacement);
    else
      out.points.add(x, CollocationRowKind::Traction, solid.normal(x).normalized());
  }
  out.interior = static_cast<Index>(interior.size());
  out.box = static_cast<Index>(box.size());
  out.surface = static_cast<Index>(surface.size());
  out.surfaceSpacing.assign(out.points.size(), 0);
  // each surface point's spacing: the mean distance to its 2 (D - 1) nearest other surface points
  // within two spacings (the buckets' reach; dx for a lone point). On a line of points spaced a, b,
  // a, b, ... it is (a + b) / 2, the point's tributary length.
  PointBuckets<D> all(solid.lower, 2 * dx);
  for (const Vec<D>& x : surface) all.add(x);
  for (std::size_t k = 0; k < surface.size(); ++k) {
    const std::vector<Real> d = all.distances(surface[k], tolerance);
    const std::size_t used = std::min<std::size_t>(d.size(), 2 * (D - 1));
    Real spacing = dx;
    if (used > 0) {
      spacing = 0;
      for (std::size_t j = 0; j < used; ++j) spacing += d[j] / static_cast<Real>(used);
    }
    out.surfaceSpacing[static_cast<std::size_t>(out.interior + out.box) + k] = spacing;
  }
  for (const Vec<D>& x : out.points.points)
    for (int a = 0; a < D; ++a) out.nodes[static_cast<std::size_t>(a)].push_back(x[a]);
  return out;
}

template SolidCollocationNodes<2> solidCollocationNodes<2>(const CollocationSolid<2>&, Real, Real, Real);
template SolidCollocationNodes<3> solidCollocationNodes<3>(const CollocationSolid<3>&, Real, Real, Real);

}  // namespace mfwave
