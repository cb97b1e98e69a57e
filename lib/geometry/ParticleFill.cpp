#include "geometry/ParticleFill.hpp"

#include "core/Error.hpp"
#include "geometry/CellShare.hpp"
#include "geometry/LatticeWindow.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <unordered_map>

namespace mfwave {
namespace {

// One lattice cell that meets the solid, before slivers are merged.
template <int D>
struct FillCandidate {
  std::array<Index, D> node;
  Vec<D> point;      // where the particle sits before merging
  CellShare<D> share;
  bool cut;          // the surface cuts the cell (not wholly inside)
  bool kept;
};

// Index of the kept candidate nearest candidates[sliver], searching rings of cells around it
// (Chebyshev radius 1, 2, ...) through `keptAt`. Every particle sits within half a cell of its
// node, so those of ring q are at least (q - 1) dx away: the search stops at the first ring that
// cannot hold anything nearer than the best found.
template <int D>
std::size_t nearestKept(const std::vector<FillCandidate<D>>& candidates, std::size_t sliver,
                        const std::unordered_map<Index, std::size_t>& keptAt, const LatticeWindow<D>& window,
                        Real dx) {
  const FillCandidate<D>& s = candidates[sliver];
  std::size_t best = std::numeric_limits<std::size_t>::max();
  Real bestSquared = std::numeric_limits<Real>::infinity();
  Index widest = 0;
  for (const Index e : window.extent) widest = std::max(widest, e);
  for (Index ring = 1; ring <= widest; ++ring) {
    const Real closest = static_cast<Real>(ring - 1) * dx;
    if (closest * closest >= bestSquared) break;
    // Walk the cube of side 2 ring + 1 and look at its shell only.
    const Index side = 2 * ring + 1;
    Index total = 1;
    for (int a = 0; a < D; ++a) total *= side;
    for (Index k = 0; k < total; ++k) {
      std::array<Index, D> node = s.node;
      Index rest = k, reach = 0;
      for (std::size_t a = 0; a < static_cast<std::size_t>(D); ++a) {
        const Index step = rest % side - ring;
        rest /= side;
        node[a] += step;
        reach = std::max(reach, std::abs(step));
      }
      if (reach != ring) continue;
      const Index offset = window.offset(node);
      if (offset < 0) continue;
      const auto found = keptAt.find(offset);
      if (found == keptAt.end()) continue;
      const Real squared = (candidates[found->second].point - s.point).squaredNorm();
      if (squared < bestSquared) {
        bestSquared = squared;
        best = found->second;
      }
    }
  }
  return best;
}

// A centroid outside the solid (a cell wrapped around a small hole or a concave corner, or a
// merge across one) moved onto the nearest surface: x - d n lands on it for an exact distance, a
// few repeats for CSG's conservative one.
template <int D>
Vec<D> insideOrOnSurface(const Solid<D>& solid, Vec<D> x) {
  for (int k = 0; k < 4; ++k) {
    const Real d = solid.signedDistance(x);
    if (d <= 0) break;
    x -= d * solid.normal(x);
  }
  return x;
}

}  // namespace

template <int D>
SolidParticles<D> fill(const Solid<D>& solid, Real dx, const Vec<D>& origin, const FillOptions& options) {
  if (options.depth < 0 || options.depth > 8)
    throw InputError("fill.depth", "must be within 0..8, got " + std::to_string(options.depth));
  if (!(options.sliverFraction >= 0 && options.sliverFraction < 1))
    throw InputError("fill.sliver_fraction", "must be within [0, 1), got " + std::to_string(options.sliverFraction));
  const LatticeWindow<D> window = latticeWindow<D>(solid.bounds(), dx, origin, 0.5 * dx);
  const Real cellVolume = std::pow(dx, D);

  std::vector<FillCandidate<D>> candidates;
  const Index cells = window.count();
  for (Index k = 0; k < cells; ++k) {
    FillCandidate<D> c;
    c.node = window.node(k);
    const Vec<D> x = latticePoint<D>(origin, dx, c.node);
    c.share = cellShare<D>(solid, x, dx, options.depth);
    if (!(c.share.volume > 0)) continue;
    c.cut = c.share.volume < cellVolume * (1 - 1e-9);
    c.point = c.cut ? Vec<D>(c.share.moment / c.share.volume) : x;
    c.kept = c.share.volume >= options.sliverFraction * cellVolume;
    candidates.push_back(c);
  }
  if (candidates.empty()) return {};

  // With no cell above the threshold (a solid thinner than the slivers), the largest one is kept.
  if (std::none_of(candidates.begin(), candidates.end(), [](const FillCandidate<D>& c) { return c.kept; })) {
    std::max_element(candidates.begin(), candidates.end(), [](const FillCandidate<D>& p, const FillCandidate<D>& q) {
      return p.share.volume < q.share.volume;
    })->kept = true;
  }
  std::unordered_map<Index, std::size_t> keptAt;
  for (std::size_t i = 0; i < candidates.size(); ++i)
    if (candidates[i].kept) keptAt.emplace(window.offset(candidates[i].node), i);

  // Receivers are found from the positions before any merge, so the order of merging does not matter.
  std::vector<CellShare<D>> merged(candidates.size());
  for (std::size_t i = 0; i < candidates.size(); ++i) merged[i] = candidates[i].share;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (candidates[i].kept) continue;
    const std::size_t to = nearestKept<D>(candidates, i, keptAt, window, dx);
    if (to >= candidates.size()) throw Error("fill: no kept particle within the lattice window to take a sliver");
    merged[to].volume += candidates[i].share.volume;
    merged[to].moment += candidates[i].share.moment;
    merged[to].area += candidates[i].share.area;
  }

  SolidParticles<D> particles;
  particles.position.reserve(keptAt.size());
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const FillCandidate<D>& c = candidates[i];
    if (!c.kept) continue;
    const CellShare<D>& m = merged[i];
    const Vec<D> x = c.cut ? insideOrOnSurface<D>(solid, m.moment / m.volume) : c.point;
    const bool onSurface = m.area > 0;
    particles.position.push_back(x);
    particles.volume.push_back(m.volume);
    particles.surface.push_back(onSurface ? 1 : 0);
    particles.normal.push_back(onSurface ? solid.normal(x) : Vec<D>::Zero());
    particles.area.push_back(onSurface ? m.area : 0.0);
    particles.cell.push_back(c.node);
  }
  return particles;
}

template SolidParticles<2> fill<2>(const Solid<2>&, Real, const Vec2&, const FillOptions&);
template SolidParticles<3> fill<3>(const Solid<3>&, Real, const Vec3&, const FillOptions&);

}  // namespace mfwave
