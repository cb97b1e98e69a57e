#include "observers/PositionSnapshots.hpp"

#include "core/Error.hpp"

#include <algorithm>
#include <string>

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

template <int D>
void PositionSnapshots<D>::saveState(StateArchive& archive) const {
  std::vector<Real> times, positions;
  for (const Snapshot& snap : snapshots_) {
    times.push_back(snap.time);
    const std::size_t count = snap.positions[0].size();
    for (std::size_t i = 0; i < count; ++i)
      for (int a = 0; a < D; ++a) positions.push_back(snap.positions[static_cast<std::size_t>(a)][i]);
  }
  archive.putScalar("next", static_cast<Real>(next_));
  archive.put("times", std::move(times));
  archive.put("positions", std::move(positions));
}

template <int D>
void PositionSnapshots<D>::restoreState(const StateArchive& archive) {
  const long next = archive.integer("next");
  const std::vector<Real>& times = archive.get("times");
  const std::vector<Real>& positions = archive.get("positions");
  const std::size_t count = static_cast<std::size_t>(positions_.size());
  if (next < 0 || static_cast<std::size_t>(next) > times_.size() || positions.size() != times.size() * count * D)
    throw InputError("--restart", "the checkpoint's position snapshots are not of " + std::to_string(count) +
                                      " particles at this run's times");
  next_ = static_cast<std::size_t>(next);
  snapshots_.clear();
  for (std::size_t k = 0; k < times.size(); ++k) {
    Snapshot snap{times[k], {}};
    for (int a = 0; a < D; ++a) snap.positions[static_cast<std::size_t>(a)].resize(count);
    for (std::size_t i = 0; i < count; ++i)
      for (int a = 0; a < D; ++a)
        snap.positions[static_cast<std::size_t>(a)][i] = positions[(k * count + i) * D + static_cast<std::size_t>(a)];
    snapshots_.push_back(std::move(snap));
  }
}

template class PositionSnapshots<1>;
template class PositionSnapshots<2>;
template class PositionSnapshots<3>;

}  // namespace mfwave
