// CellList: grid layout from the bounding box, and the stable parallel counting sort.

#include "neighbours/CellList.hpp"

#include <omp.h>

#include <limits>
#include <string>

namespace mfwave {

namespace {

// Below this many particles the OpenMP fork costs more than the loop.
constexpr Index kBinningParallelThreshold = 16384;
// Cells are made at least this much larger than R, so that rounding in the cell coordinate of
// two particles at distance just below R can never put them two cells apart.
constexpr Real kCellMargin = 1e-9;

}  // namespace

template <int D>
CellList<D>::CellList(Real radius) : radius_(radius) {
  if (!std::isfinite(radius) || radius <= 0) {
    throw InputError("radius", "search radius must be positive and finite, got " + std::to_string(radius));
  }
  inverseCellSize_.fill(1 / radius);
  cellStart_.assign(2, 0);
}

template <int D>
CellList<D>::CellList(const Coordinates<D>& coordinates, Real radius) : CellList(radius) {
  rebuild(coordinates);
}

template <int D>
CellList<D>::CellList(const ParticleSet<D>& set, Real radius) : CellList(radius) {
  rebuild(set.coordinates());
}

template <int D>
void CellList<D>::layOutGrid(const Vec<D>& lower, const Vec<D>& upper, Index particles) {
  const Real minimumCell = radius_ * (1 + kCellMargin);
  // Bounded so that a far-flung particle cannot overflow the integer conversion.
  const Real maximumPerAxis = 1e12;
  std::array<Index, D> n{};
  Real total = 1;
  for (int a = 0; a < D; ++a) {
    const Real cellsFit = std::min((upper[a] - lower[a]) / minimumCell, maximumPerAxis);
    n[static_cast<std::size_t>(a)] = std::max<Index>(1, static_cast<Index>(std::floor(cellsFit)));
    total *= static_cast<Real>(n[static_cast<std::size_t>(a)]);
  }
  // Sparse, spread-out clouds: enlarge cells until there are O(N) of them (memory and the
  // per-cell prefix sum stay proportional to the particles, not to the box volume).
  const Real maximumCells = static_cast<Real>(std::max<Index>(64, particles));
  while (total > maximumCells) {
    const Real shrink = std::pow(total / maximumCells, Real(1) / D);
    total = 1;
    for (auto& count : n) {
      count = std::max<Index>(1, static_cast<Index>(std::floor(static_cast<Real>(count) / shrink)));
      total *= static_cast<Real>(count);
    }
  }
  origin_ = lower;
  cellCount_ = 1;
  for (int a = 0; a < D; ++a) {
    const auto s = static_cast<std::size_t>(a);
    const Real size = std::max((upper[a] - lower[a]) / static_cast<Real>(n[s]), minimumCell);
    inverseCellSize_[s] = 1 / size;
    cells_[s] = n[s];
    cellCount_ *= n[s];
  }
}

template <int D>
void CellList<D>::rebuild(const Coordinates<D>& coordinates) {
  const Index count = static_cast<Index>(coordinates[0].size());
  for (const auto& axis : coordinates) {
    if (static_cast<Index>(axis.size()) != count) {
      throw InputError("positions", "coordinate arrays of different lengths");
    }
  }
  const bool parallel = count >= kBinningParallelThreshold;

  // Bounding box of the current positions (recomputed every build: particles move).
  Vec<D> lower = Vec<D>::Zero();
  Vec<D> upper = Vec<D>::Zero();
  if (count > 0) {
    // One parallel region for all axes (array reductions): every fork/join costs a timeslice
    // when the cores are shared.
    Real lo[D];
    Real hi[D];
    for (int a = 0; a < D; ++a) {
      lo[a] = std::numeric_limits<Real>::infinity();
      hi[a] = -std::numeric_limits<Real>::infinity();
    }
    Index bad = 0;
#pragma omp parallel for if (parallel) reduction(min : lo[:D]) reduction(max : hi[:D]) reduction(+ : bad)
    for (Index i = 0; i < count; ++i) {
      for (int a = 0; a < D; ++a) {
        const Real x = coordinates[static_cast<std::size_t>(a)][static_cast<std::size_t>(i)];
        lo[a] = std::min(lo[a], x);
        hi[a] = std::max(hi[a], x);
        bad += std::isfinite(x) ? 0 : 1;
      }
    }
    if (bad > 0) {
      throw Error("CellList: " + std::to_string(bad) + " particle coordinate(s) are not finite");
    }
    for (int a = 0; a < D; ++a) {
      lower[a] = lo[a];
      upper[a] = hi[a];
    }
  }
  layOutGrid(lower, upper, count);

  // Cell of every particle.
  cellOfParticle_.resize(static_cast<std::size_t>(count));
  {
    Index* cellOf = cellOfParticle_.data();
#pragma omp parallel for if (parallel)
    for (Index i = 0; i < count; ++i) {
      Index linear = 0;
      for (int a = D - 1; a >= 0; --a) {
        const auto s = static_cast<std::size_t>(a);
        const Real u = (coordinates[s][static_cast<std::size_t>(i)] - origin_[a]) * inverseCellSize_[s];
        const Index c = std::clamp<Index>(static_cast<Index>(u), 0, cells_[s] - 1);  // u >= 0
        linear = linear * cells_[s] + c;
      }
      cellOf[i] = linear;
    }
  }

  // Stable counting sort in contiguous chunks: each chunk counts its particles per cell, an
  // exclusive scan over (cell, chunk) gives each chunk its own write position inside every
  // cell, and each chunk scatters its particles in index order. The result is the unique
  // stable order, whatever the number of chunks or threads.
  const Index cellsTotal = cellCount_;
  Index chunks = 1;
  if (parallel) {
    // Per-chunk histograms cost chunks * cells memory; keep that within a few times N.
    chunks = std::max<Index>(1, std::min<Index>(omp_get_max_threads(), 4 * count / cellsTotal));
  }
  chunkOffsets_.assign(static_cast<std::size_t>(chunks * cellsTotal), 0);
  Index* offsets = chunkOffsets_.data();
  const Index* cellOf = cellOfParticle_.data();
#pragma omp parallel for if (chunks > 1) schedule(static, 1)
  for (Index k = 0; k < chunks; ++k) {
    Index* histogram = offsets + k * cellsTotal;
    for (Index i = count * k / chunks; i < count * (k + 1) / chunks; ++i) ++histogram[cellOf[i]];
  }
  cellStart_.resize(static_cast<std::size_t>(cellsTotal + 1));
  Index running = 0;
  for (Index c = 0; c < cellsTotal; ++c) {
    cellStart_[static_cast<std::size_t>(c)] = running;
    for (Index k = 0; k < chunks; ++k) {
      const Index inChunk = offsets[k * cellsTotal + c];
      offsets[k * cellsTotal + c] = running;
      running += inChunk;
    }
  }
  cellStart_[static_cast<std::size_t>(cellsTotal)] = running;

  sortedIndex_.resize(static_cast<std::size_t>(count));
  for (auto& axis : sortedCoords_) axis.resize(static_cast<std::size_t>(count));
#pragma omp parallel for if (chunks > 1) schedule(static, 1)
  for (Index k = 0; k < chunks; ++k) {
    Index* next = offsets + k * cellsTotal;
    for (Index i = count * k / chunks; i < count * (k + 1) / chunks; ++i) {
      const auto slot = static_cast<std::size_t>(next[cellOf[i]]++);
      sortedIndex_[slot] = i;
      for (std::size_t a = 0; a < static_cast<std::size_t>(D); ++a) {
        sortedCoords_[a][slot] = coordinates[a][static_cast<std::size_t>(i)];
      }
    }
  }
}

template class CellList<1>;
template class CellList<2>;
template class CellList<3>;

}  // namespace mfwave
