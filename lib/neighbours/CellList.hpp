#pragma once
// Uniform-grid cell list for fixed-radius neighbour search.
//
// Why a cell list: meshfree methods need, for every particle, all particles within the support
// radius R. Binning particles into cells of edge >= R means every such neighbour lies in the
// same or an adjacent cell, so a search touches 3^D cells instead of all N particles.
//
// Layout: particles are sorted by cell with a stable counting sort (O(N), no maps), and the
// cell list keeps its own copy of the coordinates in that order. Queries therefore stream over
// contiguous memory and do not depend on the caller's arrays staying alive. Within a cell the
// particles are in increasing index order, which is what makes results deterministic.
//
// Moving particles: rebuild() recomputes the bounding box, the grid and the sort from the
// current positions, reusing the storage of the previous build. Particles may go anywhere;
// when the box becomes large and sparse the cells are enlarged (never shrunk below R) so
// that the number of cells stays O(N).
//
// Distance rule: a particle j is a neighbour of a point x when |x - x_j| < r, strictly. Kernels
// vanish at their support radius, so points exactly at distance r contribute nothing anyway.

#include "core/Error.hpp"
#include "core/Types.hpp"
#include "particles/ParticleSet.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace mfwave {

template <int D>
class CellList {
  static_assert(D >= 1 && D <= 3, "CellList supports 1, 2 and 3 dimensions");

 public:
  // Empty list for search radius `radius`; throws InputError("radius", ...) unless radius is
  // positive and finite.
  explicit CellList(Real radius);
  CellList(const Coordinates<D>& coordinates, Real radius);
  CellList(const ParticleSet<D>& set, Real radius);

  // Rebuild from the current positions (all particles of the set, ghosts included).
  void rebuild(const Coordinates<D>& coordinates);
  void rebuild(const ParticleSet<D>& set) { rebuild(set.coordinates()); }

  Real radius() const { return radius_; }
  Index size() const { return static_cast<Index>(sortedIndex_.size()); }
  Index cellCount() const { return cellCount_; }
  Index cellsAlong(int axis) const { return cells_[static_cast<std::size_t>(axis)]; }
  Real cellSize(int axis) const { return 1 / inverseCellSize_[static_cast<std::size_t>(axis)]; }
  const Vec<D>& origin() const { return origin_; }

  // Cell-sorted storage, for search algorithms built on the cell list (NeighbourList):
  // the particles of cell c occupy slots [cellStart()[c], cellStart()[c+1]); slot s holds
  // particle sortedIndex()[s] at coordinates sortedCoordinate(a)[s].
  const std::vector<Index>& cellStart() const { return cellStart_; }
  const std::vector<Index>& sortedIndex() const { return sortedIndex_; }
  const std::vector<Real>& sortedCoordinate(int axis) const {
    return sortedCoords_[static_cast<std::size_t>(axis)];
  }

  // Integer cell coordinates of point x (unused axes 0). Points outside the grid get -1 or
  // cellsAlong(a) on that axis, so that far-away points cannot overflow.
  std::array<Index, 3> cellOfPoint(const Vec<D>& x) const {
    std::array<Index, 3> c{0, 0, 0};
    for (int a = 0; a < D; ++a) {
      const auto s = static_cast<std::size_t>(a);
      const Real u = (x[a] - origin_[a]) * inverseCellSize_[s];
      c[s] = static_cast<Index>(std::floor(std::clamp(u, Real(-1), static_cast<Real>(cells_[s]))));
    }
    return c;
  }

  // Calls rangeCallback(begin, end) for the slot ranges of all cells within one cell of
  // `cell` (at most 3^(D-1) ranges: the x-neighbours of a cell are consecutive in storage).
  template <class RangeCallback>
  void forEachSlotRange(const std::array<Index, 3>& cell, RangeCallback&& rangeCallback) const {
    std::array<Index, 3> lo{0, 0, 0};
    std::array<Index, 3> hi{0, 0, 0};
    for (std::size_t a = 0; a < static_cast<std::size_t>(D); ++a) {
      lo[a] = std::max<Index>(0, cell[a] - 1);
      hi[a] = std::min<Index>(cells_[a] - 1, cell[a] + 1);
      if (lo[a] > hi[a]) return;
    }
    for (Index z = lo[2]; z <= hi[2]; ++z) {
      for (Index y = lo[1]; y <= hi[1]; ++y) {
        const Index row = cells_[0] * (y + cells_[1] * z);
        const Index begin = cellStart_[static_cast<std::size_t>(row + lo[0])];
        const Index end = cellStart_[static_cast<std::size_t>(row + hi[0] + 1)];
        if (begin < end) rangeCallback(begin, end);
      }
    }
  }

  // Calls callback(j, distanceSquared) for every particle j with |x - x_j| < queryRadius
  // (strict), in cell order (not sorted by j). x may lie anywhere, also outside the grid.
  // Throws InputError("radius", ...) when queryRadius exceeds radius().
  template <class Callback>
  void forEachNeighbour(const Vec<D>& x, Real queryRadius, Callback&& callback) const {
    if (!(queryRadius <= radius_)) {
      throw InputError("radius", "query radius exceeds the cell list's search radius");
    }
    const Real r2 = queryRadius * queryRadius;
    forEachSlotRange(cellOfPoint(x), [&](Index begin, Index end) {
      for (Index s = begin; s < end; ++s) {
        Real d2 = 0;
        for (int a = 0; a < D; ++a) {
          const Real d = sortedCoords_[static_cast<std::size_t>(a)][static_cast<std::size_t>(s)] - x[a];
          d2 += d * d;
        }
        if (d2 < r2) callback(sortedIndex_[static_cast<std::size_t>(s)], d2);
      }
    });
  }

 private:
  void layOutGrid(const Vec<D>& lower, const Vec<D>& upper, Index particles);

  Real radius_;
  Vec<D> origin_ = Vec<D>::Zero();
  std::array<Index, 3> cells_{1, 1, 1};  // cells per axis, unused axes 1
  std::array<Real, D> inverseCellSize_{};
  Index cellCount_ = 1;
  std::vector<Index> cellStart_;     // cellCount_ + 1 slot offsets
  std::vector<Index> sortedIndex_;   // particle index per slot
  Coordinates<D> sortedCoords_;      // coordinates per slot
  std::vector<Index> cellOfParticle_;  // scratch: cell of each particle
  std::vector<Index> chunkOffsets_;    // scratch: per (chunk, cell) counts, then offsets
};

extern template class CellList<1>;
extern template class CellList<2>;
extern template class CellList<3>;

}  // namespace mfwave
