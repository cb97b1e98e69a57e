#include "numerics/Fragments.hpp"

#include <algorithm>
#include <numeric>

#include "neighbours/CellList.hpp"
#include "neighbours/NeighbourList.hpp"

namespace mfwave {

Index Fragments::particlesOutsideLargest(Index keep) const {
  Index outside = 0;
  for (Index f = keep; f < count(); ++f) outside += sizes[static_cast<std::size_t>(f)];
  return outside;
}

namespace {

Index root(std::vector<Index>& parent, Index i) {
  while (parent[static_cast<std::size_t>(i)] != i) {
    auto& p = parent[static_cast<std::size_t>(i)];
    p = parent[static_cast<std::size_t>(p)];  // path halving
    i = p;
  }
  return i;
}

}  // namespace

Fragments findFragments(const Coordinates<2>& positions, Real linkDistance) {
  const Index n = static_cast<Index>(positions[0].size());
  Fragments result;
  if (n == 0) return result;
  const NeighbourList neighbours = buildNeighbourList(CellList<2>(positions, linkDistance));
  std::vector<Index> parent(static_cast<std::size_t>(n));
  std::iota(parent.begin(), parent.end(), Index(0));
  for (Index i = 0; i < n; ++i)
    for (Index j : neighbours.row(i)) {
      const Index a = root(parent, i), b = root(parent, j);
      if (a != b) parent[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
    }
  // Components by root, then renumbered largest first (ties: by lowest particle index).
  std::vector<Index> rootOf(static_cast<std::size_t>(n)), sizeOfRoot(static_cast<std::size_t>(n), 0);
  for (Index i = 0; i < n; ++i) {
    rootOf[static_cast<std::size_t>(i)] = root(parent, i);
    ++sizeOfRoot[static_cast<std::size_t>(rootOf[static_cast<std::size_t>(i)])];
  }
  std::vector<Index> roots;
  for (Index i = 0; i < n; ++i)
    if (sizeOfRoot[static_cast<std::size_t>(i)] > 0) roots.push_back(i);
  std::stable_sort(roots.begin(), roots.end(), [&](Index a, Index b) {
    return sizeOfRoot[static_cast<std::size_t>(a)] > sizeOfRoot[static_cast<std::size_t>(b)];
  });
  std::vector<Index> number(static_cast<std::size_t>(n), -1);
  for (std::size_t k = 0; k < roots.size(); ++k) {
    number[static_cast<std::size_t>(roots[k])] = static_cast<Index>(k);
    result.sizes.push_back(sizeOfRoot[static_cast<std::size_t>(roots[k])]);
  }
  result.label.resize(static_cast<std::size_t>(n));
  for (Index i = 0; i < n; ++i)
    result.label[static_cast<std::size_t>(i)] = number[static_cast<std::size_t>(rootOf[static_cast<std::size_t>(i)])];
  return result;
}

std::vector<std::pair<Index, Index>> linkPairs(const Coordinates<2>& positions, Real linkDistance) {
  std::vector<std::pair<Index, Index>> links;
  const Index n = static_cast<Index>(positions[0].size());
  if (n == 0) return links;
  const NeighbourList neighbours = buildNeighbourList(CellList<2>(positions, linkDistance));
  for (Index i = 0; i < n; ++i)
    for (Index j : neighbours.row(i))
      if (j > i) links.emplace_back(i, j);
  return links;
}

Index tornLinks(const std::vector<std::pair<Index, Index>>& links, const Coordinates<2>& positions, Real length) {
  Index torn = 0;
  for (const auto& [i, j] : links) {
    const Real dx = positions[0][static_cast<std::size_t>(i)] - positions[0][static_cast<std::size_t>(j)];
    const Real dy = positions[1][static_cast<std::size_t>(i)] - positions[1][static_cast<std::size_t>(j)];
    if (dx * dx + dy * dy > length * length) ++torn;
  }
  return torn;
}

}  // namespace mfwave
