#include "decomposition/BlockDecomposition.hpp"

#include "core/Error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace mfwave {

namespace {

// How many nodes of [lo, hi) on `axis` have compact index c.
template <int D>
Index nodesWithCompactIndex(const LatticeRowTypes<D>& types, int axis, Index c, Index lo, Index hi) {
  const std::array<Index, 2> run = types.nodesOfCompactIndex(axis, c);
  return std::max<Index>(0, std::min(hi, run[1]) - std::max(lo, run[0]));
}

// The cost of the nodes of `box`: every type's cost times how many of its nodes the box holds.
template <int D>
Real boxCost(const LatticeRowTypes<D>& types, const std::vector<Real>& typeCost, const Box<D>& box) {
  const auto& compact = types.compactNodes();
  std::array<std::vector<Index>, D> counts;
  for (int a = 0; a < D; ++a) {
    const auto s = static_cast<std::size_t>(a);
    for (Index c = 0; c < compact[s]; ++c) counts[s].push_back(nodesWithCompactIndex(types, a, c, box.lo[s], box.hi[s]));
  }
  Box<D> all;
  all.hi = compact;
  Real total = 0;
  all.forEachNode([&](const std::array<Index, D>& c) {
    Real multiplicity = 1;
    for (std::size_t s = 0; s < static_cast<std::size_t>(D); ++s) multiplicity *= static_cast<Real>(counts[s][static_cast<std::size_t>(c[s])]);
    if (multiplicity > 0) total += multiplicity * (typeCost.empty() ? 1.0 : typeCost[static_cast<std::size_t>(all.localIndex(c))]);
  });
  return total;
}

// The cost of each lattice plane across `axis`.
template <int D>
std::vector<Real> marginalCost(const LatticeRowTypes<D>& types, const std::vector<Real>& typeCost, int axis) {
  const auto s = static_cast<std::size_t>(axis);
  Box<D> plane;
  plane.hi = types.nodes();
  std::vector<Real> byCompactIndex(static_cast<std::size_t>(types.compactNodes()[s]));
  for (Index c = 0; c < types.compactNodes()[s]; ++c) {
    // A node of compact index c, and the plane through it.
    const Index node = types.nodesOfCompactIndex(axis, c)[0];
    plane.lo[s] = node;
    plane.hi[s] = node + 1;
    byCompactIndex[static_cast<std::size_t>(c)] = boxCost(types, typeCost, plane);
  }
  std::vector<Real> marginal(static_cast<std::size_t>(types.nodes()[s]));
  for (Index i = 0; i < types.nodes()[s]; ++i)
    marginal[static_cast<std::size_t>(i)] = byCompactIndex[static_cast<std::size_t>(types.compactIndex(axis, i))];
  return marginal;
}

// Cuts `marginal` into `parts` runs of at least one node, each cut where the running cost is
// nearest the balanced share.
std::vector<Index> balancedCuts(const std::vector<Real>& marginal, int parts) {
  const auto n = static_cast<Index>(marginal.size());
  std::vector<Real> prefix(marginal.size() + 1, 0.0);
  for (std::size_t i = 0; i < marginal.size(); ++i) prefix[i + 1] = prefix[i] + marginal[i];
  std::vector<Index> cuts(static_cast<std::size_t>(parts) + 1, 0);
  cuts.back() = n;
  for (int k = 1; k < parts; ++k) {
    const Real target = prefix.back() * static_cast<Real>(k) / static_cast<Real>(parts);
    const Index lowest = cuts[static_cast<std::size_t>(k) - 1] + 1;  // every block keeps a node
    const Index highest = n - (parts - k);
    Index best = lowest;
    for (Index i = lowest; i <= highest; ++i)
      if (std::abs(prefix[static_cast<std::size_t>(i)] - target) < std::abs(prefix[static_cast<std::size_t>(best)] - target)) best = i;
    cuts[static_cast<std::size_t>(k)] = best;
  }
  return cuts;
}

// The grid of `ranks` blocks with the fewest nodes on the faces between blocks (the first found
// in the order of enumeration when several tie), or an all-zero grid when none fits the lattice.
template <int D>
std::array<int, D> smallestInterfaceGrid(const std::array<Index, D>& nodes, int ranks, const std::array<bool, D>& splittable) {
  std::array<int, D> best{};
  Real bestArea = std::numeric_limits<Real>::infinity();
  std::array<int, D> grid{};
  const auto search = [&](const auto& self, int axis, int remaining) -> void {
    const auto s = static_cast<std::size_t>(axis);
    if (axis == D - 1) {
      grid[s] = remaining;
      if (remaining > nodes[s] || (remaining > 1 && !splittable[s])) return;
      Real area = 0;
      for (int a = 0; a < D; ++a) {
        Real face = 1;
        for (int b = 0; b < D; ++b)
          if (b != a) face *= static_cast<Real>(nodes[static_cast<std::size_t>(b)]);
        area += static_cast<Real>(grid[static_cast<std::size_t>(a)] - 1) * face;
      }
      if (area < bestArea) {
        bestArea = area;
        best = grid;
      }
      return;
    }
    for (int p = 1; p <= remaining; ++p)
      if (remaining % p == 0 && p <= nodes[s] && (p == 1 || splittable[s])) {
        grid[s] = p;
        self(self, axis + 1, remaining / p);
      }
  };
  search(search, 0, ranks);
  return best;
}

}  // namespace

template <int D>
BlockDecomposition<D>::BlockDecomposition(const LatticeRowTypes<D>& types, int ranks, const std::vector<Real>& typeCost,
                                          const std::array<bool, D>& splittable)
    : types_(types), ranks_(ranks), typeCost_(typeCost) {
  if (ranks < 1) throw InputError("ranks", "must be at least 1, got " + std::to_string(ranks));
  if (!typeCost.empty()) {
    if (static_cast<Index>(typeCost.size()) != types.typeCount())
      throw InputError("cost", "one cost per row type is needed: " + std::to_string(types.typeCount()) + " types, " +
                                   std::to_string(typeCost.size()) + " costs");
    for (Real c : typeCost)
      if (!(c >= 0) || !std::isfinite(c)) throw InputError("cost", "every row type's cost must be finite and >= 0");
  }
  grid_ = smallestInterfaceGrid<D>(types.nodes(), ranks, splittable);
  if (grid_[0] == 0) {
    std::string shape;
    for (int a = 0; a < D; ++a) shape += (a ? " x " : "") + std::to_string(types.nodes()[static_cast<std::size_t>(a)]);
    throw InputError("ranks", std::to_string(ranks) + " ranks do not split a lattice of " + shape +
                                  " nodes into blocks of at least one node along the axes that may be split");
  }
  for (int a = 0; a < D; ++a)
    cuts_[static_cast<std::size_t>(a)] = balancedCuts(marginalCost(types_, typeCost_, a), grid_[static_cast<std::size_t>(a)]);
}

template <int D>
bool BlockDecomposition<D>::fits(const std::array<Index, D>& nodes, int ranks, const std::array<bool, D>& splittable) {
  return ranks >= 1 && smallestInterfaceGrid<D>(nodes, ranks, splittable)[0] != 0;
}

template <int D>
std::array<int, D> BlockDecomposition<D>::gridPosition(int rank) const {
  std::array<int, D> position{};
  for (std::size_t s = 0; s < static_cast<std::size_t>(D); ++s) {
    position[s] = rank % grid_[s];
    rank /= grid_[s];
  }
  return position;
}

template <int D>
int BlockDecomposition<D>::rankAt(const std::array<int, D>& position) const {
  int rank = 0;
  for (int a = D - 1; a >= 0; --a) rank = rank * grid_[static_cast<std::size_t>(a)] + position[static_cast<std::size_t>(a)];
  return rank;
}

template <int D>
Box<D> BlockDecomposition<D>::block(int rank) const {
  const std::array<int, D> position = gridPosition(rank);
  Box<D> box;
  for (std::size_t s = 0; s < static_cast<std::size_t>(D); ++s) {
    box.lo[s] = cuts_[s][static_cast<std::size_t>(position[s])];
    box.hi[s] = cuts_[s][static_cast<std::size_t>(position[s]) + 1];
  }
  return box;
}

template <int D>
int BlockDecomposition<D>::owner(const std::array<Index, D>& node) const {
  std::array<int, D> position{};
  for (std::size_t s = 0; s < static_cast<std::size_t>(D); ++s) {
    const auto& c = cuts_[s];
    position[s] = static_cast<int>(std::upper_bound(c.begin(), c.end(), node[s]) - c.begin()) - 1;
  }
  return rankAt(position);
}

template <int D>
Real BlockDecomposition<D>::cost(int rank) const {
  return boxCost(types_, typeCost_, block(rank));
}

template <int D>
Real BlockDecomposition<D>::imbalance() const {
  Real largest = 0, total = 0;
  for (int r = 0; r < ranks_; ++r) {
    const Real c = cost(r);
    largest = std::max(largest, c);
    total += c;
  }
  return total > 0 ? largest * static_cast<Real>(ranks_) / total : 1.0;
}

template <int D>
Index BlockDecomposition<D>::interfaceNodes() const {
  Index total = 0;
  for (int a = 0; a < D; ++a) {
    Index face = 1;
    for (int b = 0; b < D; ++b)
      if (b != a) face *= types_.nodes()[static_cast<std::size_t>(b)];
    total += (grid_[static_cast<std::size_t>(a)] - 1) * face;
  }
  return total;
}

template class BlockDecomposition<1>;
template class BlockDecomposition<2>;
template class BlockDecomposition<3>;

}  // namespace mfwave
