#include "methods/updated_lagrangian_sph/SkinnedNeighbours.hpp"

#include "core/Error.hpp"
#include "methods/updated_lagrangian_sph/ParallelThreshold.hpp"

#include <algorithm>

namespace mfwave {

template <int D>
SkinnedNeighbours<D>::SkinnedNeighbours(Real supportRadius, Real skin)
    : trigger2_(0.25 * skin * skin * supportRadius * supportRadius), cells_((1 + skin) * supportRadius) {}

template <int D>
bool SkinnedNeighbours<D>::refresh(const Real* x, Index count) {
  if (rebuilds_ == 0 || static_cast<Index>(built_[0].size()) != count) {
    rebuild(x, count);
    return true;
  }
  Real largest = 0;
#pragma omp parallel for if (count > kParallelParticles) reduction(max : largest)
  for (Index i = 0; i < count; ++i) {
    Real d2 = 0;
    for (int a = 0; a < D; ++a) {
      const Real d = x[i * D + a] - built_[static_cast<std::size_t>(a)][static_cast<std::size_t>(i)];
      d2 += d * d;
    }
    largest = std::max(largest, d2);
  }
  // Strictly more than skin R / 2: with skin 0 any motion at all rebuilds.
  if (largest > trigger2_) {
    rebuild(x, count);
    return true;
  }
  return false;
}

template <int D>
void SkinnedNeighbours<D>::rebuild(const Real* x, Index count) {
  for (int a = 0; a < D; ++a) {
    std::vector<Real>& axis = built_[static_cast<std::size_t>(a)];
    axis.resize(static_cast<std::size_t>(count));
    for (Index i = 0; i < count; ++i) axis[static_cast<std::size_t>(i)] = x[i * D + a];
  }
  cells_.rebuild(built_);
  buildNeighbourList(cells_, list_);
  if (interacts_) {
    // drop the pairs the filter separates, rows kept in order (so sums stay thread-independent)
    std::size_t kept = 0, start = 0;
    for (Index i = 0; i < list_.rowCount(); ++i) {
      const std::size_t end = static_cast<std::size_t>(list_.offsets[static_cast<std::size_t>(i) + 1]);
      for (std::size_t k = start; k < end; ++k) {
        const Index j = list_.indices[k];
        if (j == i || interacts_(i, j)) list_.indices[kept++] = j;
      }
      start = end;
      list_.offsets[static_cast<std::size_t>(i) + 1] = static_cast<Index>(kept);
    }
    list_.indices.resize(kept);
  }
  ++rebuilds_;
}

template <int D>
void SkinnedNeighbours<D>::saveState(StateArchive& archive) const {
  std::vector<Real> built;  // particle-major, as refresh() takes positions
  const std::size_t count = built_[0].size();
  built.reserve(count * D);
  for (std::size_t i = 0; i < count; ++i)
    for (int a = 0; a < D; ++a) built.push_back(built_[static_cast<std::size_t>(a)][i]);
  archive.put("built", std::move(built));
  archive.putScalar("rebuilds", static_cast<Real>(rebuilds_));
}

template <int D>
void SkinnedNeighbours<D>::restoreState(const StateArchive& archive) {
  const std::vector<Real>& built = archive.get("built");
  const long rebuilds = archive.integer("rebuilds");
  if (rebuilds < 1 || built.size() % D != 0)
    throw InputError("--restart", "the checkpoint's neighbour lists are not those of a " + std::to_string(D) +
                                      "-D particle system");
  rebuild(built.data(), static_cast<Index>(built.size() / D));
  rebuilds_ = rebuilds;  // rebuild() counted one more
}

template class SkinnedNeighbours<1>;
template class SkinnedNeighbours<2>;
template class SkinnedNeighbours<3>;

}  // namespace mfwave
