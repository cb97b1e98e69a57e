#include "lattice/LatticeRowTypes.hpp"

#include "core/Error.hpp"

#include <algorithm>
#include <string>

namespace mfwave {

template <int D>
LatticeRowTypes<D>::LatticeRowTypes(const std::array<Index, D>& nodes, Index depth) : nodes_(nodes), depth_(depth) {
  if (depth < 1) throw InputError("lattice", "the row-type depth must be at least 1, got " + std::to_string(depth));
  for (int a = 0; a < D; ++a) {
    const auto s = static_cast<std::size_t>(a);
    if (nodes[s] < 1) throw InputError("lattice", "axis " + std::to_string(a) + " has no nodes");
    compact_[s] = std::min(nodes[s], 2 * depth + 1);
  }
}

template <int D>
Index LatticeRowTypes<D>::nodeCount() const {
  Index count = 1;
  for (Index n : nodes_) count *= n;
  return count;
}

template <int D>
Index LatticeRowTypes<D>::typeCount() const {
  Index count = 1;
  for (Index n : compact_) count *= n;
  return count;
}

template <int D>
Index LatticeRowTypes<D>::typeOf(const std::array<Index, D>& node) const {
  Index type = 0;
  for (int a = D - 1; a >= 0; --a)
    type = type * compact_[static_cast<std::size_t>(a)] + compactIndex(a, node[static_cast<std::size_t>(a)]);
  return type;
}

template <int D>
std::array<Index, D> LatticeRowTypes<D>::node(Index p) const {
  std::array<Index, D> node{};
  for (int a = 0; a < D; ++a) {
    const auto s = static_cast<std::size_t>(a);
    node[s] = p % nodes_[s];
    p /= nodes_[s];
  }
  return node;
}

template class LatticeRowTypes<1>;
template class LatticeRowTypes<2>;
template class LatticeRowTypes<3>;

}  // namespace mfwave
