#pragma once
// A box of lattice nodes, [lo, hi) per axis, and the few operations a domain decomposition (or any
// work on part of a lattice) needs: its size, the intersection of two boxes, growth by a stencil's
// reach (stencilReach) clipped to the lattice, and a walk over its nodes in the lattice's own order
// (x fastest, LatticeRowTypes.hpp), which is the order every halo message is packed and unpacked in.

#include "core/Types.hpp"

#include <algorithm>
#include <array>

namespace mfwave {

template <int D>
struct Box {
  std::array<Index, D> lo{};
  std::array<Index, D> hi{};

  bool empty() const {
    for (int a = 0; a < D; ++a)
      if (hi[static_cast<std::size_t>(a)] <= lo[static_cast<std::size_t>(a)]) return true;
    return false;
  }
  Index count() const {
    if (empty()) return 0;
    Index n = 1;
    for (int a = 0; a < D; ++a) n *= hi[static_cast<std::size_t>(a)] - lo[static_cast<std::size_t>(a)];
    return n;
  }
  Index extent(int axis) const { return hi[static_cast<std::size_t>(axis)] - lo[static_cast<std::size_t>(axis)]; }
  bool contains(const std::array<Index, D>& node) const {
    for (int a = 0; a < D; ++a) {
      const auto s = static_cast<std::size_t>(a);
      if (node[s] < lo[s] || node[s] >= hi[s]) return false;
    }
    return true;
  }
  // The position of `node` (inside the box) in the box's own x-fastest numbering.
  Index localIndex(const std::array<Index, D>& node) const {
    Index index = 0;
    for (int a = D - 1; a >= 0; --a) index = index * extent(a) + (node[static_cast<std::size_t>(a)] - lo[static_cast<std::size_t>(a)]);
    return index;
  }
  // The node numbered `index` in the box's own x-fastest numbering (localIndex's inverse).
  std::array<Index, D> node(Index index) const {
    std::array<Index, D> n = lo;
    for (int a = 0; a < D; ++a) {
      n[static_cast<std::size_t>(a)] += index % extent(a);
      index /= extent(a);
    }
    return n;
  }
  bool operator==(const Box& other) const { return lo == other.lo && hi == other.hi; }
  bool operator!=(const Box& other) const { return !(*this == other); }

  // The lines of the box along x (count() / extent(0) of them), numbered x-fastest over the other
  // axes as their nodes are, and the first node of line l: a walk over lines touches each node's
  // storage contiguously, and lines can be shared among threads by number.
  Index lineCount() const { return empty() ? 0 : count() / extent(0); }
  std::array<Index, D> lineStart(Index line) const {
    std::array<Index, D> node = lo;
    for (int a = 1; a < D; ++a) {
      const auto s = static_cast<std::size_t>(a);
      node[s] = lo[s] + line % extent(a);
      line /= extent(a);
    }
    return node;
  }

  // Calls visit(node) for every node of the box, x fastest.
  template <class Visit>
  void forEachNode(Visit&& visit) const {
    if (empty()) return;
    std::array<Index, D> node = lo;
    while (true) {
      visit(static_cast<const std::array<Index, D>&>(node));
      int a = 0;
      for (; a < D; ++a) {
        const auto s = static_cast<std::size_t>(a);
        if (++node[s] < hi[s]) break;
        node[s] = lo[s];
      }
      if (a == D) return;
    }
  }
};

template <int D>
Box<D> intersection(const Box<D>& a, const Box<D>& b) {
  Box<D> c;
  for (std::size_t s = 0; s < static_cast<std::size_t>(D); ++s) {
    c.lo[s] = std::max(a.lo[s], b.lo[s]);
    c.hi[s] = std::max(c.lo[s], std::min(a.hi[s], b.hi[s]));
  }
  return c;
}

// `box` grown by `reach` nodes on every side, clipped to the lattice of `nodes` per axis: the nodes
// a stencil of that reach reads from the box's rows.
template <int D>
Box<D> grown(const Box<D>& box, const std::array<Index, D>& reach, const std::array<Index, D>& nodes) {
  Box<D> g;
  for (std::size_t s = 0; s < static_cast<std::size_t>(D); ++s) {
    g.lo[s] = std::max<Index>(0, box.lo[s] - reach[s]);
    g.hi[s] = std::min(nodes[s], box.hi[s] + reach[s]);
  }
  return g;
}

}  // namespace mfwave
