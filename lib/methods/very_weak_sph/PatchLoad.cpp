#include "methods/very_weak_sph/PatchLoad.hpp"

#include "core/Error.hpp"
#include "particles/BoxFace.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace mfwave {

namespace {

// Length of [lo1, hi1] intersect [lo2, hi2] (0 when they do not overlap).
Real overlap(Real lo1, Real hi1, Real lo2, Real hi2) { return std::max(Real(0), std::min(hi1, hi2) - std::max(lo1, lo2)); }

// int of the tent of half-width s centred at 0 from -infinity to t.
Real tentIntegralBelow(Real t, Real s) {
  t = std::clamp(t, -s, s);
  return t < 0 ? (t + s) * (t + s) / (2 * s) : s - (s - t) * (s - t) / (2 * s);
}

enum class PatchWeight { CellFraction, Tent };

template <int D>
std::vector<Real> patchWeights(const ParticleSet<D>& particles, int face, const Vec<D>& centre,
                               const Vec<D>& halfWidths, Real spacing, const Vec<D>& boxLower,
                               const Vec<D>& boxUpper, PatchWeight kind) {
  if (face < 0 || face >= 2 * D)
    throw InputError("patch.face", "face " + std::to_string(face) + " does not exist on a " + std::to_string(D) +
                                       "-D box");
  if (!(spacing > 0) || !std::isfinite(spacing)) throw InputError("spacing", "must be > 0");
  const int normalAxis = faceAxis(face);
  for (int j = 0; j < D; ++j) {
    if (j == normalAxis) continue;
    if (!(halfWidths[j] >= 0) || !std::isfinite(halfWidths[j]) || !std::isfinite(centre[j]))
      throw InputError("patch.half_widths", std::string("must be >= 0 and finite along ") + axisName(j));
    if (!(boxUpper[j] > boxLower[j])) throw InputError("geometry", std::string("empty box along ") + axisName(j));
  }
  const Index n = particles.physicalCount();
  std::vector<Real> weight(static_cast<std::size_t>(n), 0.0);
  for (Index a = 0; a < n; ++a) {
    if ((particles.faceMask[static_cast<std::size_t>(a)] & faceBit(face)) == 0) continue;
    const Vec<D> x = particles.position(a);
    // Ding-Long-Wu eq. (37) integrated over the particle's cell (or against its tent), clipped to the face.
    Real fraction = 1;
    for (int j = 0; j < D; ++j) {
      if (j == normalAxis) continue;
      if (kind == PatchWeight::Tent) {  // the rectangle clipped to the face, relative to the particle
        const Real lo = std::max(centre[j] - halfWidths[j], boxLower[j]) - x[j];
        const Real hi = std::min(centre[j] + halfWidths[j], boxUpper[j]) - x[j];
        fraction *= hi > lo ? (tentIntegralBelow(hi, spacing) - tentIntegralBelow(lo, spacing)) / spacing : 0;
      } else {
        const Real cellLo = std::max(x[j] - spacing / 2, boxLower[j]);
        const Real cellHi = std::min(x[j] + spacing / 2, boxUpper[j]);
        fraction *= overlap(cellLo, cellHi, centre[j] - halfWidths[j], centre[j] + halfWidths[j]) / spacing;
      }
    }
    weight[static_cast<std::size_t>(a)] = fraction;
  }
  return weight;
}

}  // namespace

template <int D>
std::vector<Real> patchLoadWeights(const ParticleSet<D>& particles, int face, const Vec<D>& centre,
                                   const Vec<D>& halfWidths, Real spacing, const Vec<D>& boxLower,
                                   const Vec<D>& boxUpper) {
  return patchWeights(particles, face, centre, halfWidths, spacing, boxLower, boxUpper, PatchWeight::CellFraction);
}

template <int D>
std::vector<Real> patchTentWeights(const ParticleSet<D>& particles, int face, const Vec<D>& centre,
                                   const Vec<D>& halfWidths, Real spacing, const Vec<D>& boxLower,
                                   const Vec<D>& boxUpper) {
  return patchWeights(particles, face, centre, halfWidths, spacing, boxLower, boxUpper, PatchWeight::Tent);
}

template <int D>
Vector patchNodalForce(const std::vector<Real>& weights, Real spacing, const Vec<D>& traction) {
  Vector f = Vector::Zero(static_cast<Index>(D * weights.size()));
  const Real area = std::pow(spacing, D - 1);
  for (std::size_t a = 0; a < weights.size(); ++a)
    f.template segment<D>(static_cast<Index>(D * a)) = weights[a] * area * traction;
  return f;
}

template <int D>
Vector patchFacetTractions(const BoundaryFacets<D>& facets, int face, const std::vector<Real>& weights,
                           const Vec<D>& traction) {
  if (face < 0 || face >= 2 * D) throw InputError("patch.face", "face " + std::to_string(face) + " does not exist");
  if (static_cast<Index>(weights.size()) + 1 != static_cast<Index>(facets.offsets.size()))
    throw InputError("patch.weights", "need one weight per physical particle");
  Vector t = Vector::Zero(D * facets.count());
  for (Index f = 0; f < facets.count(); ++f) {
    const auto k = static_cast<std::size_t>(f);
    if (facets.face[k] != face) continue;  // the other facets of an edge or corner particle carry no load
    t.template segment<D>(D * f) = weights[static_cast<std::size_t>(facets.particle[k])] * traction;
  }
  return t;
}

#define MFWAVE_INSTANTIATE(D)                                                                               \
  template std::vector<Real> patchLoadWeights<D>(const ParticleSet<D>&, int, const Vec<D>&, const Vec<D>&, \
                                                 Real, const Vec<D>&, const Vec<D>&);                      \
  template std::vector<Real> patchTentWeights<D>(const ParticleSet<D>&, int, const Vec<D>&, const Vec<D>&, \
                                                 Real, const Vec<D>&, const Vec<D>&);                      \
  template Vector patchNodalForce<D>(const std::vector<Real>&, Real, const Vec<D>&);                        \
  template Vector patchFacetTractions<D>(const BoundaryFacets<D>&, int, const std::vector<Real>&, const Vec<D>&);
MFWAVE_INSTANTIATE(1)
MFWAVE_INSTANTIATE(2)
MFWAVE_INSTANTIATE(3)
#undef MFWAVE_INSTANTIATE

}  // namespace mfwave
