#pragma once
// The split of a box lattice into one block per rank (issue 22): a grid of p_0 x ... x p_{D-1} = P
// blocks, the grid chosen to make the faces between blocks (the halo the ranks exchange) as small
// as possible, and each axis cut where the cost of the nodes on either side balances.
//
// The cost of a node is the cost of its row type (LatticeRowTypes.hpp): by default 1 per node (a
// balance by particle count), or per type, e.g. the stencil entries plus dashpot work of the rows
// near absorbing faces, which cost more than interior rows. Cuts are made axis by axis on the
// marginal cost (the cost of each lattice plane across the axis), computed from the compact lattice
// with each compact node's multiplicity, so set-up is O(nodes per axis x types), not O(nodes):
// a 10^9-node lattice decomposes in milliseconds. A product of per-axis cuts balances exactly a
// cost that is a product of per-axis factors; for the face rows of a box it is close, and
// imbalance() says how close.
//
// Ranks are numbered over the grid x fastest, as the lattice's nodes are.

#include "core/Types.hpp"
#include "lattice/Box.hpp"
#include "lattice/LatticeRowTypes.hpp"

#include <array>
#include <vector>

namespace mfwave {

template <int D>
class BlockDecomposition {
 public:
  // Throws InputError("ranks") for ranks < 1 or more ranks than the lattice has nodes along the
  // splittable axes, InputError("cost") for a cost list of the wrong length or a negative or
  // non-finite cost. `typeCost` empty: every node costs 1. `splittable[a]` false keeps axis a whole:
  // with x whole every rank owns whole lattice lines, whose sums (energies, norms) are then the
  // serial ones, combined in the serial order by sumInLatticeOrder (mpi/LineSums.hpp); with x split
  // the pieces of a line chain their running sums there instead.
  BlockDecomposition(const LatticeRowTypes<D>& types, int ranks, const std::vector<Real>& typeCost = {},
                     const std::array<bool, D>& splittable = allAxes());

  static std::array<bool, D> allAxes() {
    std::array<bool, D> all{};
    all.fill(true);
    return all;
  }
  // Whether `ranks` blocks of at least one node each fit a lattice of `nodes` cutting only the
  // `splittable` axes (else the constructor throws InputError("ranks")): a caller that prefers to
  // keep an axis whole asks first.
  static bool fits(const std::array<Index, D>& nodes, int ranks, const std::array<bool, D>& splittable);

  int ranks() const { return ranks_; }
  const std::array<Index, D>& nodes() const { return types_.nodes(); }
  // Blocks per axis.
  const std::array<int, D>& grid() const { return grid_; }
  // The grid position of a rank and the rank at a grid position.
  std::array<int, D> gridPosition(int rank) const;
  int rankAt(const std::array<int, D>& position) const;
  // The nodes a rank owns.
  Box<D> block(int rank) const;
  // The rank that owns a node.
  int owner(const std::array<Index, D>& node) const;
  // Where the blocks along `axis` begin: cuts(axis)[k] is the first node of block k, and the last
  // entry is the node count.
  const std::vector<Index>& cuts(int axis) const { return cuts_[static_cast<std::size_t>(axis)]; }
  // The cost of a rank's block, the largest over the mean (1: perfect balance), and the nodes on
  // the faces between blocks (each face counted once: the halo a stencil of reach 1 exchanges).
  Real cost(int rank) const;
  Real imbalance() const;
  Index interfaceNodes() const;

 private:
  LatticeRowTypes<D> types_;
  int ranks_ = 1;
  std::vector<Real> typeCost_;
  std::array<int, D> grid_{};
  std::array<std::vector<Index>, D> cuts_;
};

extern template class BlockDecomposition<1>;
extern template class BlockDecomposition<2>;
extern template class BlockDecomposition<3>;

}  // namespace mfwave
