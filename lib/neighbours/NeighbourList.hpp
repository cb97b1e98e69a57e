#pragma once
// Neighbour lists in compressed-row (CSR) form, built from a CellList.
//
// Why CSR: the lists are traversed many times per build (every right-hand-side evaluation of
// a fixed-particle run reuses them), so they are stored as two flat arrays that stream well
// and carry no per-row allocation. Row i is indices[offsets[i] .. offsets[i+1]).
//
// Contents: row i holds every particle j with |x_i - x_j| < R (strictly, see CellList.hpp),
// including i itself (SPH-type sums contain the self term), sorted by increasing j. The sort
// makes the lists, and every sum taken over them, independent of the number of threads.

#include "core/Types.hpp"
#include "neighbours/CellList.hpp"

#include <vector>

namespace mfwave {

struct NeighbourList {
  std::vector<Index> offsets;  // rowCount() + 1 entries, offsets[0] == 0
  std::vector<Index> indices;  // neighbours, row by row, sorted within each row

  Index rowCount() const { return offsets.empty() ? 0 : static_cast<Index>(offsets.size()) - 1; }
  Index totalCount() const { return static_cast<Index>(indices.size()); }
  Index count(Index i) const {
    return offsets[static_cast<std::size_t>(i) + 1] - offsets[static_cast<std::size_t>(i)];
  }
  // Pointer range of row i, for range-for loops: for (Index j : list.row(i)) ...
  struct Row {
    const Index* first;
    const Index* last;
    const Index* begin() const { return first; }
    const Index* end() const { return last; }
  };
  Row row(Index i) const {
    const Index* base = indices.data();
    return {base + offsets[static_cast<std::size_t>(i)], base + offsets[static_cast<std::size_t>(i) + 1]};
  }
  // Mean row length (self included); 0 for an empty list.
  Real meanCount() const {
    return rowCount() > 0 ? static_cast<Real>(totalCount()) / static_cast<Real>(rowCount()) : 0;
  }
};

// Builds rows for particles [0, rows) (rows < 0: all particles in the cell list) against all
// particles, e.g. rows = set.physicalCount() to skip the ghosts' own rows while ghosts still
// appear as neighbours. Two OpenMP passes over the cells: count per row, exclusive scan, fill
// and sort. `list` is overwritten; its storage is reused across rebuilds.
template <int D>
void buildNeighbourList(const CellList<D>& cells, NeighbourList& list, Index rows = -1);

template <int D>
NeighbourList buildNeighbourList(const CellList<D>& cells, Index rows = -1) {
  NeighbourList list;
  buildNeighbourList(cells, list, rows);
  return list;
}

extern template void buildNeighbourList<1>(const CellList<1>&, NeighbourList&, Index);
extern template void buildNeighbourList<2>(const CellList<2>&, NeighbourList&, Index);
extern template void buildNeighbourList<3>(const CellList<3>&, NeighbourList&, Index);

}  // namespace mfwave
