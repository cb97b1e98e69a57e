#include "observers/PositionSnapshots.hpp"

#include <algorithm>

namespace mfwave {

template <int D>
PositionSnapshots<D>::PositionSnapshots(const ParticleSet<D>& positions, std::vector<Real> times, bool addDisplacement)
    : positions_(positions), times_(std::move(times)), addDisplacement_(addDisplacement) {}

template <int D>
void PositionSnapshots<D>::take(const StateView& state, bool last) {
  if (!state.displacement.allFinite()) return;
  // A time reached up to round-off counts as reached.
  const Real slack = 1e-9 * (times_.empty() ? 1 : std::max(times_.back(), Real(1e-300)));
  while (next_ < times_.size() && (last || state.time >= times_[next_] - slack)) {
    Snapshot snap{state.time, positions_.coordinates()};
    if (addDisplacement_)
      for (int a = 0; a < D; ++a)
        for (std::size_t i = 0; i < snap.positions[static_cast<std::size_t>(a)].size(); ++i)
          snap.positions[static_cast<std::size_t>(a)][i] += state.displacement[static_cast<Index>(i) * D + a];
    snapshots_.push_back(std::move(snap));
    ++next_;
    if (!last) break;  // one snapshot per state: later times wait for later states
  }
}

template class PositionSnapshots<1>;
template class PositionSnapshots<2>;
template class PositionSnapshots<3>;

}  // namespace mfwave
