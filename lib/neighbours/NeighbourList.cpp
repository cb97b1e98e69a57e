// NeighbourList: the two-pass parallel CSR build over the cells of a CellList.
//
// The inner loops are branch-free (the comparison result is added to a counter or to the
// write cursor): in a random cloud only ~15% of the candidates in the 3^D cells are within R, in
// no predictable pattern, and a mispredicted branch per candidate costs more than the
// distance itself.

#include "neighbours/NeighbourList.hpp"

#include "core/Error.hpp"

#include <algorithm>
#include <array>
#include <string>
#include <utility>

namespace mfwave {

namespace {

// Below this many particles the OpenMP fork costs more than the search.
constexpr Index kPairListParallelThreshold = 4096;

// Rows arrive as runs sorted per cell; when particles are numbered spatially (lattices) the
// whole row is nearly sorted. Insertion sort is linear then, and no slower than std::sort at
// typical row lengths otherwise.
void sortRow(Index* first, Index* last) {
  if (last - first > 96) {
    std::sort(first, last);
    return;
  }
  for (Index* p = first + 1; p < last; ++p) {
    const Index value = *p;
    Index* q = p;
    for (; q > first && *(q - 1) > value; --q) *q = *(q - 1);
    *q = value;
  }
}

// The candidate slots for the particles of one cell: the slot ranges of the up to 3^(D-1)
// rows of neighbouring cells (x-neighbours are consecutive in storage), gathered once per cell.
template <int D>
class CellNeighbourhood {
 public:
  CellNeighbourhood(const CellList<D>& cells, Index c) : r2_(cells.radius() * cells.radius()) {
    std::array<Index, 3> cell{0, 0, 0};
    Index rest = c;
    for (int a = 0; a < D; ++a) {
      cell[static_cast<std::size_t>(a)] = rest % cells.cellsAlong(a);
      rest /= cells.cellsAlong(a);
    }
    cells.forEachSlotRange(cell, [this](Index begin, Index end) {
      ranges_[rangeCount_++] = {begin, end};
    });
    for (int a = 0; a < D; ++a) x_[static_cast<std::size_t>(a)] = cells.sortedCoordinate(a).data();
  }

  // Number of candidates strictly within R of slot s. Counted in a Real (exact below 2^53):
  // a comparison feeding a floating-point add vectorises on baseline x86-64 (SSE2), one
  // feeding a 64-bit integer add does not.
  Index count(Index s) const {
    const auto xi = coordinatesOf(s);
    Real found = 0;
    for (std::size_t r = 0; r < rangeCount_; ++r) {
      for (Index t = ranges_[r].first; t < ranges_[r].second; ++t) found += inside(xi, t) ? 1.0 : 0.0;
    }
    return static_cast<Index>(found);
  }

  // Writes the particle indices of the rowLength candidates strictly within R of slot s (the
  // count from pass 1) to row. Branch-free: every candidate is written at the cursor, which
  // only advances for those inside; the loop stops when the row is full, so no write ever
  // lands beyond the row (the next row may belong to another thread).
  // Returns how many were found: rowLength unless the two passes disagreed.
  Index collect(Index s, const Index* particle, Index* row, Index rowLength) const {
    const auto xi = coordinatesOf(s);
    Index found = 0;
    if (rowLength == 0) return 0;
    for (std::size_t r = 0; r < rangeCount_; ++r) {
      for (Index t = ranges_[r].first; t < ranges_[r].second; ++t) {
        row[found] = particle[t];
        found += inside(xi, t) ? 1 : 0;
        if (found == rowLength) return found;
      }
    }
    return found;
  }

 private:
  std::array<Real, D> coordinatesOf(Index s) const {
    std::array<Real, D> xi;
    for (std::size_t a = 0; a < static_cast<std::size_t>(D); ++a) xi[a] = x_[a][s];
    return xi;
  }
  bool inside(const std::array<Real, D>& xi, Index t) const {
    Real d2 = 0;
    for (std::size_t a = 0; a < static_cast<std::size_t>(D); ++a) {
      const Real d = x_[a][t] - xi[a];
      d2 += d * d;
    }
    return d2 < r2_;
  }

  std::array<std::pair<Index, Index>, 9> ranges_{};
  std::size_t rangeCount_ = 0;
  std::array<const Real*, D> x_{};
  Real r2_;
};

}  // namespace

template <int D>
void buildNeighbourList(const CellList<D>& cells, NeighbourList& list, Index rows) {
  const Index total = cells.size();
  if (rows < 0) rows = total;
  if (rows > total) {
    throw InputError("rows", "asked for " + std::to_string(rows) + " rows but the cell list holds " +
                                 std::to_string(total) + " particles");
  }
  const Index cellCount = cells.cellCount();
  const bool parallel = total >= kPairListParallelThreshold;
  const Index* start = cells.cellStart().data();
  const Index* particle = cells.sortedIndex().data();

  // Pass 1: row lengths into offsets[i + 1]; then the exclusive scan makes them offsets.
  list.offsets.assign(static_cast<std::size_t>(rows) + 1, 0);
  Index* offsets = list.offsets.data();
#pragma omp parallel for if (parallel) schedule(dynamic, 16)
  for (Index c = 0; c < cellCount; ++c) {
    if (start[c] == start[c + 1]) continue;
    const CellNeighbourhood<D> neighbourhood(cells, c);
    for (Index s = start[c]; s < start[c + 1]; ++s) {
      if (particle[s] < rows) offsets[particle[s] + 1] = neighbourhood.count(s);
    }
  }
  for (Index i = 0; i < rows; ++i) offsets[i + 1] += offsets[i];

  // Pass 2: fill each row at its offset and sort it, so the order does not depend on the
  // cell layout or on which thread handled the row.
  list.indices.resize(static_cast<std::size_t>(offsets[rows]));
  Index* indices = list.indices.data();
  bool mismatch = false;
#pragma omp parallel for if (parallel) schedule(dynamic, 16) reduction(|| : mismatch)
  for (Index c = 0; c < cellCount; ++c) {
    if (start[c] == start[c + 1]) continue;
    const CellNeighbourhood<D> neighbourhood(cells, c);
    for (Index s = start[c]; s < start[c + 1]; ++s) {
      const Index i = particle[s];
      if (i >= rows) continue;
      Index* row = indices + offsets[i];
      const Index length = offsets[i + 1] - offsets[i];
      if (neighbourhood.collect(s, particle, row, length) != length) mismatch = true;
      sortRow(row, row + length);
    }
  }
  // The passes evaluate the same expression; they can only disagree if the compiler fused
  // multiply-adds differently in the two loops, which the -ffp-contract=off of this target
  // rules out. Never hand out a list with stale entries.
  if (mismatch) throw Error("buildNeighbourList: count and fill passes disagree (floating-point contraction?)");
}

template void buildNeighbourList<1>(const CellList<1>&, NeighbourList&, Index);
template void buildNeighbourList<2>(const CellList<2>&, NeighbourList&, Index);
template void buildNeighbourList<3>(const CellList<3>&, NeighbourList&, Index);

}  // namespace mfwave
