#include "methods/very_weak_sph/CutCellGalerkin.hpp"

#include "core/Error.hpp"
#include "geometry/PlaneCut.hpp"
#include "particles/BoxFace.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace mfwave {
namespace {

constexpr Real kGauss = 0.57735026918962576451;  // 1 / sqrt 3: the 2-point Gauss rule on [-1, 1]

// The tents of a cell's 2^D corners at a point: corner k has bit a of k set when it is the cell's
// upper node along axis a. t is the point's position in the cell, in [0, 1]^D inside it.
template <int D>
Real cornerTent(const Vec<D>& t, int k) {
  Real w = 1;
  for (int a = 0; a < D; ++a) w *= ((k >> a) & 1) ? t[a] : 1 - t[a];
  return w;
}

// Corner k of `cell` (bit a of k: the upper node along axis a), as in cornerTent.
template <int D>
std::array<Index, D> cornerOf(std::array<Index, D> cell, int k) {
  for (int a = 0; a < D; ++a) cell[static_cast<std::size_t>(a)] += (k >> a) & 1;
  return cell;
}

template <int D>
Vec<D> cornerTentGradient(const Vec<D>& t, int k, Real spacing) {
  Vec<D> g;
  for (int a = 0; a < D; ++a) {
    Real w = ((k >> a) & 1) ? 1 / spacing : -1 / spacing;
    for (int b = 0; b < D; ++b)
      if (b != a) w *= ((k >> b) & 1) ? t[b] : 1 - t[b];
    g[a] = w;
  }
  return g;
}

// The tensor 2-point Gauss points of a box [lower, lower + size]^D (or of its face across `skip`).
template <int D>
void gaussPointsOf(const Vec<D>& lower, Real size, int skip, std::vector<std::pair<Vec<D>, Real>>& out) {
  int dims = 0;
  for (int a = 0; a < D; ++a) dims += a == skip ? 0 : 1;
  const Real weight = std::pow(size / 2, dims);
  for (int k = 0; k < (1 << D); ++k) {
    bool valid = true;
    Vec<D> x = lower;
    for (int a = 0; a < D; ++a) {
      if (a == skip) {
        valid = valid && ((k >> a) & 1) == 0;
        continue;
      }
      x[a] += size / 2 * (1 + (((k >> a) & 1) ? kGauss : -kGauss));
    }
    if (valid) out.emplace_back(x, weight);
  }
}

}  // namespace

template <int D>
Index CutCellGalerkin<D>::nodeIndex(const std::array<Index, D>& node) const {
  Index index = 0;
  for (int a = D - 1; a >= 0; --a) index = index * nodes_[static_cast<std::size_t>(a)] + node[static_cast<std::size_t>(a)];
  return index;
}

template <int D>
std::array<Index, D> CutCellGalerkin<D>::nodeOf(Index index) const {
  std::array<Index, D> node{};
  for (int a = 0; a < D; ++a) {
    node[static_cast<std::size_t>(a)] = index % nodes_[static_cast<std::size_t>(a)];
    index /= nodes_[static_cast<std::size_t>(a)];
  }
  return node;
}

template <int D>
Vec<D> CutCellGalerkin<D>::position(const std::array<Index, D>& node) const {
  Vec<D> x;
  for (int a = 0; a < D; ++a) x[a] = settings_.lower[a] + static_cast<Real>(node[static_cast<std::size_t>(a)]) * settings_.spacing;
  return x;
}

// Recursive: a sub-cell wholly outside contributes nothing, one wholly inside one material its
// Gauss points, one the surface or an interface may cut is split, and at the last level its Gauss
// points count where they are inside (each with its own material). In 2-D the last level's cut
// sub-cells also give the surface (marching squares on the corner distances).
template <int D>
void CutCellGalerkin<D>::cellPoints(const Vec<D>& lower, Real size, int level, std::vector<Point>& out, bool& cut) {
  const Vec<D> centre = lower + Vec<D>::Constant(size / 2);
  const Real reach = size * std::sqrt(static_cast<Real>(D)) / 2;
  const Real d = domain_.distance(centre);
  if (d > reach) return;
  const Real interfaceGap = domain_.interfaceDistance ? domain_.interfaceDistance(centre)
                                                      : std::numeric_limits<Real>::infinity();
  std::vector<std::pair<Vec<D>, Real>> gauss;
  if (d < -reach && interfaceGap > reach) {
    gaussPointsOf<D>(lower, size, -1, gauss);
    const int material = domain_.materialAt(centre);
    for (const auto& [x, w] : gauss) out.push_back({x, w, material});
    return;
  }
  cut = cut || d >= -reach;
  if (level < settings_.depth) {
    for (int k = 0; k < (1 << D); ++k) {
      Vec<D> child = lower;
      for (int a = 0; a < D; ++a)
        if ((k >> a) & 1) child[a] += size / 2;
      cellPoints(child, size / 2, level + 1, out, cut);
    }
    return;
  }
  gaussPointsOf<D>(lower, size, -1, gauss);
  for (const auto& [x, w] : gauss)
    if (domain_.distance(x) <= 0) out.push_back({x, w, domain_.materialAt(x)});
  if constexpr (D == 3) {
    // the surface in a last-level sub-cell as the plane tangent at the point nearest its centre
    // (normal from the distance's gradient): its area inside the sub-cell in closed form
    // (geometry/PlaneCut), one point at that nearest point. Exact for a flat surface; a curved one
    // errs by the order of (curvature x side)^2 per sub-cell.
    const Real e = 1e-3 * size;
    Vec3 gradient;
    for (int a = 0; a < 3; ++a) {
      Vec3 step = Vec3::Zero();
      step[a] = e;
      gradient[a] = (domain_.distance(centre + step) - domain_.distance(centre - step)) / (2 * e);
    }
    if (gradient.norm() > 0) {
      const Vec3 n = gradient.normalized();
      // at the nearest point, kept in the sub-cell (near a corner it can lie just outside)
      const Vec3 foot = (centre - d * n).cwiseMax(lower).cwiseMin(lower + Vec3::Constant(size));
      const Real area = planeCutOfUnitCube<3>(n, -d / size).area * size * size;
      if (area > 0) surface_.push_back({foot, n, area});
    }
  }
  if constexpr (D == 2) {
    // marching squares on the corners: outside where the distance is > 0
    Real s[4];
    Vec2 corner[4];
    for (int k = 0; k < 4; ++k) {
      corner[k] = lower + Vec2(((k & 1) ? size : 0), ((k & 2) ? size : 0));
      s[k] = domain_.distance(corner[k]);
    }
    // the square's edges in order around it: (0,1), (1,3), (3,2), (2,0)
    static const int edges[4][2] = {{0, 1}, {1, 3}, {3, 2}, {2, 0}};
    std::vector<Vec2> crossings;
    for (const auto& e : edges) {
      const bool outA = s[e[0]] > 0, outB = s[e[1]] > 0;
      if (outA == outB) continue;
      const Real f = s[e[0]] / (s[e[0]] - s[e[1]]);
      crossings.push_back(corner[e[0]] + f * (corner[e[1]] - corner[e[0]]));
    }
    std::vector<std::pair<Vec2, Vec2>> segments;
    if (crossings.size() == 2) segments.emplace_back(crossings[0], crossings[1]);
    if (crossings.size() == 4) {  // a saddle: pair the crossings so that the centre's side stays connected
      const bool centreOut = d > 0, firstOut = s[0] > 0;
      if (centreOut == firstOut) {
        segments.emplace_back(crossings[0], crossings[1]);
        segments.emplace_back(crossings[2], crossings[3]);
      } else {
        segments.emplace_back(crossings[3], crossings[0]);
        segments.emplace_back(crossings[1], crossings[2]);
      }
    }
    for (const auto& [a, b] : segments) {
      const Real length = (b - a).norm();
      if (!(length > 0)) continue;
      Vec2 normal(b[1] - a[1], a[0] - b[0]);
      normal /= length;
      // orient outwards: the distance grows along it (bilinear gradient at the segment's middle)
      const Vec2 t = ((a + b) / 2 - lower) / size;
      const Vec2 gradient((1 - t[1]) * (s[1] - s[0]) + t[1] * (s[3] - s[2]), (1 - t[0]) * (s[2] - s[0]) + t[0] * (s[3] - s[1]));
      if (normal.dot(gradient) < 0) normal = -normal;
      for (const Real g : {-kGauss, kGauss})
        surface_.push_back({(a + b) / 2 + g / 2 * (b - a), normal, length / 2});
    }
  }
}

template <int D>
CutCellGalerkin<D>::CutCellGalerkin(CutCellDomain<D> domain, const CutCellSettings<D>& settings)
    : domain_(std::move(domain)), settings_(settings) {
  const Real h = settings_.spacing;
  if (!domain_.distance) throw InputError("geometry", "the cut-cell Galerkin lattice needs the solid's distance");
  if (domain_.materials.empty() || !domain_.materialAt) throw InputError("material", "no material");
  if (!(h > 0)) throw InputError("geometry.spacing", "must be positive");
  if (settings_.depth < 0 || settings_.depth > 8) throw InputError("method.cut_depth", "must be 0 .. 8");
  Index nodeCount = 1, cellCount = 1;
  std::array<Index, D> cells{};
  for (int a = 0; a < D; ++a) {
    const Real intervals = (settings_.upper[a] - settings_.lower[a]) / h;
    const auto n = static_cast<Index>(std::llround(intervals));
    if (n < 1 || std::abs(intervals - static_cast<Real>(n)) > 1e-9 * std::max<Real>(1, intervals))
      throw InputError("geometry.spacing", "must divide the box along " + std::string(axisName(a)));
    nodes_[static_cast<std::size_t>(a)] = n + 1;
    cells[static_cast<std::size_t>(a)] = n;
    nodeCount *= n + 1;
    cellCount *= n;
  }
  const int corners = 1 << D;
  const int local = D * corners;

  // 1. Each cell's quadrature points (none outside; whole cells of one material by reference).
  struct CellData {
    Index cell;
    std::vector<Point> points;  // empty for a whole cell
    int wholeMaterial = -1;
  };
  std::vector<CellData> kept;
  for (Index c = 0; c < cellCount; ++c) {
    std::array<Index, D> node{};
    Index rest = c;
    for (int a = 0; a < D; ++a) {
      node[static_cast<std::size_t>(a)] = rest % cells[static_cast<std::size_t>(a)];
      rest /= cells[static_cast<std::size_t>(a)];
    }
    const Vec<D> lower = position(node);
    const Vec<D> centre = lower + Vec<D>::Constant(h / 2);
    const Real reach = h * std::sqrt(static_cast<Real>(D)) / 2;
    const Real gap = domain_.interfaceDistance ? domain_.interfaceDistance(centre) : std::numeric_limits<Real>::infinity();
    CellData data{c, {}, -1};
    if (settings_.cells == CutCells::Staircase) {
      if (domain_.distance(centre) > 0) continue;
      if (gap > reach) {
        data.wholeMaterial = domain_.materialAt(centre);
      } else {
        std::vector<std::pair<Vec<D>, Real>> gauss;
        gaussPointsOf<D>(lower, h, -1, gauss);
        for (const auto& [x, w] : gauss) data.points.push_back({x, w, domain_.materialAt(x)});
      }
    } else {
      const Real d = domain_.distance(centre);
      if (d > reach) continue;
      if (d < -reach && gap > reach) {
        data.wholeMaterial = domain_.materialAt(centre);
      } else {
        bool cut = false;
        cellPoints(lower, h, 0, data.points, cut);
        if (data.points.empty()) continue;
        if (cut) ++cutCells_;
      }
    }
    if (data.wholeMaterial >= static_cast<int>(domain_.materials.size())) throw InputError("material", "no such material");
    for (const Point& p : data.points)
      if (p.material < 0 || p.material >= static_cast<int>(domain_.materials.size())) {
        std::ostringstream where;
        where << "the point (" << p.x.transpose() << ") of the solid lies in no material's region";
        throw InputError("material", where.str());
      }
    if (data.wholeMaterial < 0 && data.points.empty()) continue;
    kept.push_back(std::move(data));
  }
  if (kept.empty()) throw InputError("geometry", "the solid has no cell inside the lattice box");
  // The staircase's surface: the faces between a kept cell and a cell left out (the box's faces are
  // its boundary, not a surface). A pressure along each face's own normal has the resultant of the
  // true surface's (the normals times lengths of a path sum to its chord's), which is the
  // staircase's reading of a surface load.
  if (settings_.cells == CutCells::Staircase) {
    std::vector<char> inside(static_cast<std::size_t>(cellCount), 0);
    for (const CellData& c : kept) inside[static_cast<std::size_t>(c.cell)] = 1;
    for (const CellData& c : kept) {
      std::array<Index, D> cell{};
      Index rest = c.cell;
      for (int a = 0; a < D; ++a) {
        cell[static_cast<std::size_t>(a)] = rest % cells[static_cast<std::size_t>(a)];
        rest /= cells[static_cast<std::size_t>(a)];
      }
      for (int face = 0; face < 2 * D; ++face) {
        const int axis = faceAxis(face);
        const auto q = static_cast<std::size_t>(axis);
        std::array<Index, D> neighbour = cell;
        neighbour[q] += faceSign(face);
        if (neighbour[q] < 0 || neighbour[q] >= cells[q]) continue;
        Index index = 0;
        for (int a = D - 1; a >= 0; --a) index = index * cells[static_cast<std::size_t>(a)] + neighbour[static_cast<std::size_t>(a)];
        if (inside[static_cast<std::size_t>(index)]) continue;
        Vec<D> lower = position(cell);
        if (faceSign(face) > 0) lower[axis] += h;
        std::vector<std::pair<Vec<D>, Real>> gauss;
        gaussPointsOf<D>(lower, h, axis, gauss);
        for (const auto& [x, w] : gauss) surface_.push_back({x, faceNormal<D>(face), w});
      }
    }
  }

  // Element matrices: K_e(a i, b k) = sum_q w [lambda dW_a/dx_i dW_b/dx_k + mu dW_a/dx_k dW_b/dx_i
  // + mu delta_ik grad W_a . grad W_b] (C_ijkl = lambda d_ij d_kl + mu (d_ik d_jl + d_il d_jk)), the
  // lumped mass m_a = sum_q w rho W_a and the volume v_a = sum_q w W_a.
  auto elementOf = [&](const std::vector<Point>& points, const Vec<D>& lower, Eigen::MatrixXd& k, Vector& m,
                       Vector& v) {
    k.setZero(local, local);
    m.setZero(corners);
    v.setZero(corners);
    for (const Point& p : points) {
      const Material& material = domain_.materials[static_cast<std::size_t>(p.material)];
      const Real lambda = material.lambda(), mu = material.mu();
      const Vec<D> t = (p.x - lower) / h;
      std::array<Vec<D>, 1 << D> g;
      for (int a = 0; a < corners; ++a) {
        g[static_cast<std::size_t>(a)] = cornerTentGradient<D>(t, a, h);
        const Real w = cornerTent<D>(t, a);
        m[a] += p.weight * material.density() * w;
        v[a] += p.weight * w;
      }
      for (int a = 0; a < corners; ++a)
        for (int b = 0; b < corners; ++b) {
          const Vec<D>& ga = g[static_cast<std::size_t>(a)];
          const Vec<D>& gb = g[static_cast<std::size_t>(b)];
          const Real dot = ga.dot(gb);
          for (int i = 0; i < D; ++i)
            for (int kk = 0; kk < D; ++kk)
              k(D * a + i, D * b + kk) += p.weight * (lambda * ga[i] * gb[kk] + mu * ga[kk] * gb[i] + (i == kk ? mu * dot : 0));
        }
    }
  };
  // whole cells of each material: one element, made once
  std::vector<Eigen::MatrixXd> wholeK(domain_.materials.size());
  std::vector<Vector> wholeM(domain_.materials.size()), wholeV(domain_.materials.size());
  for (std::size_t m = 0; m < domain_.materials.size(); ++m) {
    std::vector<std::pair<Vec<D>, Real>> gauss;
    gaussPointsOf<D>(Vec<D>::Zero(), h, -1, gauss);
    std::vector<Point> points;
    for (const auto& [x, w] : gauss) points.push_back({x, w, static_cast<int>(m)});
    elementOf(points, Vec<D>::Zero(), wholeK[m], wholeM[m], wholeV[m]);
  }

  // 2. Active nodes (a corner of a kept cell), their mass and volume.
  active_.assign(static_cast<std::size_t>(nodeCount), -1);
  auto cornerNode = [&](Index cell, int k) {
    std::array<Index, D> node{};
    Index rest = cell;
    for (int a = 0; a < D; ++a) {
      node[static_cast<std::size_t>(a)] = rest % cells[static_cast<std::size_t>(a)] + ((k >> a) & 1);
      rest /= cells[static_cast<std::size_t>(a)];
    }
    return node;
  };
  for (const CellData& c : kept)
    for (int k = 0; k < corners; ++k) {
      const Index n = nodeIndex(cornerNode(c.cell, k));
      if (active_[static_cast<std::size_t>(n)] < 0) {
        active_[static_cast<std::size_t>(n)] = static_cast<Index>(activeNode_.size());
        activeNode_.push_back(n);
      }
    }
  const auto activeCount = static_cast<Index>(activeNode_.size());
  Vector mass = Vector::Zero(activeCount), volume = Vector::Zero(activeCount);
  std::vector<Triplet> stiffness;
  stiffness.reserve(kept.size() * static_cast<std::size_t>(local * local));
  Eigen::MatrixXd k(local, local);
  Vector m(corners), v(corners);
  for (const CellData& c : kept) {
    const Vec<D> lower = position(cornerNode(c.cell, 0));
    const Eigen::MatrixXd* ke = &k;
    const Vector* me = &m;
    const Vector* ve = &v;
    if (c.wholeMaterial >= 0) {
      ke = &wholeK[static_cast<std::size_t>(c.wholeMaterial)];
      me = &wholeM[static_cast<std::size_t>(c.wholeMaterial)];
      ve = &wholeV[static_cast<std::size_t>(c.wholeMaterial)];
    } else {
      elementOf(c.points, lower, k, m, v);
    }
    Index ids[1 << D];
    for (int a = 0; a < corners; ++a) ids[a] = active_[static_cast<std::size_t>(nodeIndex(cornerNode(c.cell, a)))];
    for (int a = 0; a < corners; ++a) {
      mass[ids[a]] += (*me)[a];
      volume[ids[a]] += (*ve)[a];
      for (int b = 0; b < corners; ++b)
        for (int i = 0; i < D; ++i)
          for (int kk = 0; kk < D; ++kk) {
            const Real value = (*ke)(D * a + i, D * b + kk);
            if (value != 0) stiffness.emplace_back(static_cast<int>(D * ids[a] + i), static_cast<int>(D * ids[b] + kk), value);
          }
    }
  }
  volume_ = volume.sum();

  // 3. Unknowns: the active nodes whose volume is at least smallCellFraction of their volume in the
  // uncut box; the others are extended from the nearest cell of unknowns.
  unknownOf_.assign(static_cast<std::size_t>(activeCount), -1);
  extension_.assign(static_cast<std::size_t>(activeCount), {});
  for (Index a = 0; a < activeCount; ++a) {
    const std::array<Index, D> node = nodeOf(activeNode_[static_cast<std::size_t>(a)]);
    Real boxVolume = std::pow(h, D);
    for (int ax = 0; ax < D; ++ax)
      if (node[static_cast<std::size_t>(ax)] == 0 || node[static_cast<std::size_t>(ax)] == nodes_[static_cast<std::size_t>(ax)] - 1)
        boxVolume /= 2;
    const Real fraction = volume[a] / boxVolume;
    const bool keep = settings_.cells == CutCells::Staircase || fraction >= settings_.smallCellFraction;
    if (!keep) continue;
    smallestKept_ = std::min(smallestKept_, fraction);
    unknownOf_[static_cast<std::size_t>(a)] = static_cast<Index>(unknownPosition_.size());
    unknownPosition_.push_back(position(node));
  }
  for (Index a = 0; a < activeCount; ++a) {
    if (unknownOf_[static_cast<std::size_t>(a)] >= 0) continue;
    ++extendedNodes_;
    const std::array<Index, D> node = nodeOf(activeNode_[static_cast<std::size_t>(a)]);
    const Vec<D> x = position(node);
    Real best = std::numeric_limits<Real>::infinity();
    std::array<Index, D> bestCell{};
    // cells whose lower corner is within two nodes of this one
    int span = 1;
    for (int ax = 0; ax < D; ++ax) span *= 4;
    for (int s = 0; s < span; ++s) {
      std::array<Index, D> cell{};
      bool inBox = true;
      int code = s;
      for (int ax = 0; ax < D; ++ax) {
        const auto q = static_cast<std::size_t>(ax);
        cell[q] = node[q] + code % 4 - 2;
        code /= 4;
        inBox = inBox && cell[q] >= 0 && cell[q] < cells[q];
      }
      if (!inBox) continue;
      bool allUnknown = true;
      for (int kc = 0; kc < corners && allUnknown; ++kc) {
        const Index act = active_[static_cast<std::size_t>(nodeIndex(cornerOf<D>(cell, kc)))];
        allUnknown = act >= 0 && unknownOf_[static_cast<std::size_t>(act)] >= 0;
      }
      if (!allUnknown) continue;
      const Real distance = (position(cell) + Vec<D>::Constant(h / 2) - x).norm();
      if (distance < best) {
        best = distance;
        bestCell = cell;
      }
    }
    if (!std::isfinite(best)) {
      // No cell of unknowns near (a wedge's tip, where the surface meets a box face or another surface
      // at a sharp angle): the nearest unknown node within three spacings carries it (constant
      // extension: the partition of unity is kept, the linear reproduction is lost at this node).
      Real nearest = std::numeric_limits<Real>::infinity();
      Index chosen = -1;
      for (Index b = 0; b < activeCount; ++b) {
        const Index u = unknownOf_[static_cast<std::size_t>(b)];
        if (u < 0) continue;
        const Real r = (position(nodeOf(activeNode_[static_cast<std::size_t>(b)])) - x).norm();
        if (r < nearest) {
          nearest = r;
          chosen = u;
        }
      }
      if (chosen >= 0 && nearest <= 3 * h * (1 + 1e-12)) {
        extension_[static_cast<std::size_t>(a)].emplace_back(chosen, 1.0);
        ++constantExtensions_;
        continue;
      }
      std::ostringstream where;
      where << "the node at (" << x.transpose() << ") keeps " << volume[a] / std::pow(h, D)
            << " of a cell and no cell of full nodes lies within two spacings: a part of the solid thinner "
               "than the lattice resolves; refine geometry.spacing";
      throw InputError("geometry", where.str());
    }
    const Vec<D> t = (x - position(bestCell)) / h;
    for (int kc = 0; kc < corners; ++kc) {
      const Index act = active_[static_cast<std::size_t>(nodeIndex(cornerOf<D>(bestCell, kc)))];
      const Real w = cornerTent<D>(t, kc);
      if (w != 0) extension_[static_cast<std::size_t>(a)].emplace_back(unknownOf_[static_cast<std::size_t>(act)], w);
    }
  }

  // 4. Dashpots on the transmitting box faces, over the part of each face inside the solid:
  // rho c_p on the normal component, rho c_s on the tangential ones, lumped on the node (as the
  // lattice's Galerkin variant).
  Vector dashpot = Vector::Zero(D * activeCount);
  bool anyDashpot = false;
  for (int face = 0; face < 2 * D; ++face) {
    if ((settings_.transmittingFaces & faceBit(face)) == 0) continue;
    const int axis = faceAxis(face);
    const auto q = static_cast<std::size_t>(axis);
    for (const CellData& c : kept) {
      const std::array<Index, D> lowerNode = cornerNode(c.cell, 0);
      const bool touches = faceSign(face) < 0 ? lowerNode[q] == 0 : lowerNode[q] == cells[q] - 1;
      if (!touches) continue;
      Vec<D> onFace = position(lowerNode);
      if (faceSign(face) > 0) onFace[axis] += h;
      // recursive over the face square
      std::function<void(const Vec<D>&, Real, int)> facePoints = [&](const Vec<D>& lower, Real size, int level) {
        Vec<D> centre = lower + Vec<D>::Constant(size / 2);
        centre[axis] = lower[axis];
        const Real reach = size * std::sqrt(static_cast<Real>(D - 1)) / 2;
        const Real d = domain_.distance(centre);
        if (d > reach) return;
        std::vector<std::pair<Vec<D>, Real>> gauss;
        gaussPointsOf<D>(lower, size, axis, gauss);
        const bool whole = d < -reach || settings_.cells == CutCells::Staircase;
        if (!whole && level < settings_.depth && settings_.cells == CutCells::Cut) {
          for (int kk = 0; kk < (1 << D); ++kk) {
            if ((kk >> axis) & 1) continue;
            Vec<D> child = lower;
            for (int ax = 0; ax < D; ++ax)
              if (ax != axis && ((kk >> ax) & 1)) child[ax] += size / 2;
            facePoints(child, size / 2, level + 1);
          }
          return;
        }
        for (const auto& [x, w] : gauss) {
          if (!whole && domain_.distance(x) > 0) continue;
          const Material& material = domain_.materials[static_cast<std::size_t>(domain_.materialAt(x))];
          const Vec<D> t = (x - position(lowerNode)) / h;
          for (int kc = 0; kc < corners; ++kc) {
            const Real tent = cornerTent<D>(t, kc);
            if (tent == 0) continue;
            const Index act = active_[static_cast<std::size_t>(nodeIndex(cornerNode(c.cell, kc)))];
            for (int i = 0; i < D; ++i)
              dashpot[D * act + i] += w * tent * material.density() *
                                      (i == axis ? material.pWaveSpeed() : material.sWaveSpeed());
          }
          anyDashpot = true;
        }
      };
      facePoints(onFace, h, 0);
    }
  }

  // 5. The reduced system: E maps the unknowns to every active dof.
  std::vector<Triplet> e;
  for (Index a = 0; a < activeCount; ++a)
    for (int i = 0; i < D; ++i) {
      const Index u = unknownOf_[static_cast<std::size_t>(a)];
      if (u >= 0) {
        e.emplace_back(static_cast<int>(D * a + i), static_cast<int>(D * u + i), 1.0);
        continue;
      }
      for (const auto& [unknown, w] : extension_[static_cast<std::size_t>(a)])
        e.emplace_back(static_cast<int>(D * a + i), static_cast<int>(D * unknown + i), w);
    }
  SparseMatrix extension(D * activeCount, size());
  extension.setFromTriplets(e.begin(), e.end());
  SparseMatrix full(D * activeCount, D * activeCount);
  full.setFromTriplets(stiffness.begin(), stiffness.end());
  stiffness_ = SparseMatrix(extension.transpose() * full * extension);
  stiffness_.prune(0.0);
  // The mass stays lumped and positive: an extended node's mass goes to the unknowns it is made of
  // in proportion to its positive weights (the extrapolation's weights can be negative; the row sums of
  // E^T M E could make a mass negative). The total is kept.
  Vector lumped = Vector::Zero(size());
  for (Index a = 0; a < activeCount; ++a) {
    const Index u = unknownOf_[static_cast<std::size_t>(a)];
    if (u >= 0) {
      lumped.template segment<D>(D * u).array() += mass[a];
      continue;
    }
    Real norm = 0;
    for (const auto& entry : extension_[static_cast<std::size_t>(a)]) norm += std::max<Real>(0, entry.second);
    for (const auto& [unknown, w] : extension_[static_cast<std::size_t>(a)])
      lumped.template segment<D>(D * unknown).array() += mass[a] * std::max<Real>(0, w) / norm;
  }
  for (Index i = 0; i < size(); ++i)
    if (!(lumped[i] > 0)) {
      std::ostringstream where;
      where << "the node at (" << unknownPosition_[static_cast<std::size_t>(i / D)].transpose()
            << ") has no mass; refine geometry.spacing";
      throw InputError("geometry", where.str());
    }
  mass_.resize(size(), size());
  mass_.reserve(Eigen::VectorXi::Constant(static_cast<int>(size()), 1));
  for (Index i = 0; i < size(); ++i) mass_.insert(static_cast<int>(i), static_cast<int>(i)) = lumped[i];
  mass_.makeCompressed();
  if (anyDashpot) {
    const SparseMatrix c = SparseMatrix(dashpot.asDiagonal());
    damping_ = SparseMatrix(extension.transpose() * c * extension);
    damping_.prune(0.0);
  }
}

template <int D>
Vector CutCellGalerkin<D>::reduce(const std::vector<std::pair<Index, Vec<D>>>& nodal) const {
  Vector f = Vector::Zero(size());
  for (const auto& [node, force] : nodal) {
    const Index a = active_[static_cast<std::size_t>(node)];
    if (a < 0) continue;
    const Index u = unknownOf_[static_cast<std::size_t>(a)];
    if (u >= 0) {
      f.template segment<D>(D * u) += force;
      continue;
    }
    for (const auto& [unknown, w] : extension_[static_cast<std::size_t>(a)]) f.template segment<D>(D * unknown) += w * force;
  }
  return f;
}

// The cell holding x (clamped into the box) and x's position in it.
template <int D>
static std::pair<std::array<Index, D>, Vec<D>> cellAt(const Vec<D>& x, const Vec<D>& lower, Real h,
                                                      const std::array<Index, D>& nodes) {
  std::array<Index, D> cell{};
  Vec<D> t;
  for (int a = 0; a < D; ++a) {
    const auto q = static_cast<std::size_t>(a);
    const Real s = (x[a] - lower[a]) / h;
    cell[q] = std::clamp<Index>(static_cast<Index>(std::floor(s)), 0, nodes[q] - 2);
    t[a] = s - static_cast<Real>(cell[q]);
  }
  return {cell, t};
}

template <int D>
Vector CutCellGalerkin<D>::pointForce(const Vec<D>& x, const Vec<D>& force) const {
  const auto [cell, t] = cellAt<D>(x, settings_.lower, settings_.spacing, nodes_);
  std::vector<std::pair<Index, Vec<D>>> nodal;
  for (int k = 0; k < (1 << D); ++k) nodal.emplace_back(nodeIndex(cornerOf<D>(cell, k)), cornerTent<D>(t, k) * force);
  return reduce(nodal);
}

template <int D>
Vector CutCellGalerkin<D>::momentTensor(const Vec<D>& x, const Mat<D>& moment) const {
  const auto [cell, t] = cellAt<D>(x, settings_.lower, settings_.spacing, nodes_);
  std::vector<std::pair<Index, Vec<D>>> nodal;
  // int (-M grad delta) W_a = M grad W_a(x)
  for (int k = 0; k < (1 << D); ++k)
    nodal.emplace_back(nodeIndex(cornerOf<D>(cell, k)), moment * cornerTentGradient<D>(t, k, settings_.spacing));
  return reduce(nodal);
}

template <int D>
Vector CutCellGalerkin<D>::surfaceTraction(
    const std::function<bool(const Vec<D>&)>& on,
    const std::function<Vec<D>(const Vec<D>& x, const Vec<D>& normal)>& traction) const {
  std::vector<std::pair<Index, Vec<D>>> nodal;
  for (const SurfacePoint<D>& p : surface_) {
    if (!on(p.x)) continue;
    const Vec<D> t = traction(p.x, p.normal) * p.weight;
    const auto [cell, local] = cellAt<D>(p.x, settings_.lower, settings_.spacing, nodes_);
    for (int k = 0; k < (1 << D); ++k) nodal.emplace_back(nodeIndex(cornerOf<D>(cell, k)), cornerTent<D>(local, k) * t);
  }
  return reduce(nodal);
}

template <int D>
std::vector<std::pair<Index, Real>> CutCellGalerkin<D>::interpolation(const Vec<D>& x, int component) const {
  const auto [cell, t] = cellAt<D>(x, settings_.lower, settings_.spacing, nodes_);
  std::vector<std::pair<Index, Real>> row;
  auto add = [&row](Index dof, Real w) {
    for (auto& entry : row)
      if (entry.first == dof) {
        entry.second += w;
        return;
      }
    row.emplace_back(dof, w);
  };
  for (int k = 0; k < (1 << D); ++k) {
    const Real w = cornerTent<D>(t, k);
    if (w == 0) continue;
    const Index a = active_[static_cast<std::size_t>(nodeIndex(cornerOf<D>(cell, k)))];
    if (a < 0) continue;
    const Index u = unknownOf_[static_cast<std::size_t>(a)];
    if (u >= 0) {
      add(D * u + component, w);
      continue;
    }
    for (const auto& [unknown, e] : extension_[static_cast<std::size_t>(a)]) add(D * unknown + component, w * e);
  }
  return row;
}

template class CutCellGalerkin<2>;
template class CutCellGalerkin<3>;

}  // namespace mfwave
