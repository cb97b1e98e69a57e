#pragma once
// Rows of an operator on a box lattice that differ only by where they sit relative to the faces.
//
// Away from the faces every row of a translation-invariant discretisation is the same; within
// `depth` nodes of a face it depends on the distance to that face. So a node's row type is, axis by
// axis, its distance to the lower face (when below depth), to the upper face (when below depth), or
// "interior": the node of a compact lattice of 2 depth + 1 nodes per axis (all the nodes, when the
// lattice is shorter than that) that sits the same way. An operator assembled once on the compact
// lattice gives every row of the big one (LatticeStencils), and a node's type is derived from its
// lattice position, never stored.
//
// Nodes are numbered x fastest (makeLattice's order): node (i, j, k) is i + n_x (j + n_y k).

#include "core/Types.hpp"

#include <array>

namespace mfwave {

template <int D>
class LatticeRowTypes {
 public:
  // One node, depth 1.
  LatticeRowTypes() { nodes_.fill(1); compact_.fill(1); }
  // Throws InputError("lattice") for an axis without nodes or depth < 1.
  LatticeRowTypes(const std::array<Index, D>& nodes, Index depth);

  const std::array<Index, D>& nodes() const { return nodes_; }
  const std::array<Index, D>& compactNodes() const { return compact_; }
  Index depth() const { return depth_; }
  Index nodeCount() const;
  Index typeCount() const;

  // The compact node index along `axis` of node index i on that axis.
  Index compactIndex(int axis, Index i) const {
    const Index n = nodes_[static_cast<std::size_t>(axis)];
    const Index m = compact_[static_cast<std::size_t>(axis)];
    if (n == m || i < depth_) return i;
    if (i >= n - depth_) return i - (n - m);
    return depth_;
  }
  // The nodes along `axis` whose compact index is c: [first, last), one node near a face or the
  // whole interior run.
  std::array<Index, 2> nodesOfCompactIndex(int axis, Index c) const {
    const Index n = nodes_[static_cast<std::size_t>(axis)];
    const Index m = compact_[static_cast<std::size_t>(axis)];
    if (n == m || c < depth_) return {c, c + 1};
    if (c == depth_) return {depth_, n - depth_};
    return {c + (n - m), c + (n - m) + 1};
  }
  // The row type of a node: the linear index (x fastest) of its compact node.
  Index typeOf(const std::array<Index, D>& node) const;
  // The node of linear index p.
  std::array<Index, D> node(Index p) const;

  // The same depth on a lattice with `nodes` per axis.
  LatticeRowTypes<D> on(const std::array<Index, D>& nodes) const { return LatticeRowTypes<D>(nodes, depth_); }

 private:
  std::array<Index, D> nodes_{};
  std::array<Index, D> compact_{};
  Index depth_ = 1;
};

extern template class LatticeRowTypes<1>;
extern template class LatticeRowTypes<2>;
extern template class LatticeRowTypes<3>;

}  // namespace mfwave
