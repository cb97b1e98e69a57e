#pragma once
// The lattice nodes origin + dx * i (i integer per axis) a solid's bounds can concern, for the
// particle fill (nodes whose cells reach the bounds) and the lattice methods (nodes inside the
// bounds). Shared so that both check the spacing, the origin and the bounds the same way.

#include "core/Types.hpp"
#include "geometry/Bounds.hpp"

#include <array>

namespace mfwave {

template <int D>
struct LatticeWindow {
  std::array<Index, D> first{};  // lowest node index per axis
  std::array<Index, D> extent{};  // nodes per axis (0 on any axis: no node)

  Index count() const {
    Index n = 1;
    for (const Index e : extent) n *= e;
    return n;
  }
  // The node of the k-th position in x-fastest order.
  std::array<Index, D> node(Index k) const {
    std::array<Index, D> i{};
    for (std::size_t a = 0; a < static_cast<std::size_t>(D); ++a) {
      i[a] = first[a] + k % extent[a];
      k /= extent[a];
    }
    return i;
  }
  // The position of `node` in x-fastest order, -1 outside the window.
  Index offset(const std::array<Index, D>& node) const {
    Index k = 0;
    for (std::size_t a = static_cast<std::size_t>(D); a-- > 0;) {
      const Index local = node[a] - first[a];
      if (local < 0 || local >= extent[a]) return -1;
      k = k * extent[a] + local;
    }
    return k;
  }
};

template <int D>
Vec<D> latticePoint(const Vec<D>& origin, Real dx, const std::array<Index, D>& node) {
  Vec<D> x;
  for (int a = 0; a < D; ++a) x[a] = origin[a] + dx * static_cast<Real>(node[static_cast<std::size_t>(a)]);
  return x;
}

// Nodes within `reach` of the bounds (reach dx / 2: the cells that meet them), with a margin of
// 1e-9 dx for nodes that lie on the bounds up to rounding. Throws InputError "spacing" (dx not
// positive and finite, or more than 2^31 nodes), "origin" (not finite) or "solid" (unbounded: a
// half-space must be intersected with a bounded solid first).
template <int D>
LatticeWindow<D> latticeWindow(const Bounds<D>& bounds, Real dx, const Vec<D>& origin, Real reach);

}  // namespace mfwave
