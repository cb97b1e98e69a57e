#pragma once
// Every particle's position at chosen times, from a particle view: at the first state at or after
// each time (one snapshot per state), and every time still to come at the end of the run. The
// positions come from a particle set the view keeps at the current positions (a ViewAdapter's
// moved copy), or from fixed particles plus the displacement (`addDisplacement`). Add it at every
// step so that no time is passed by.

#include "observers/Observer.hpp"
#include "particles/ParticleSet.hpp"

#include <vector>

namespace mfwave {

template <int D>
class PositionSnapshots : public Observer {
 public:
  struct Snapshot {
    Real time;
    Coordinates<D> positions;
  };

  // `positions` must outlive the recorder; `times` in increasing order.
  PositionSnapshots(const ParticleSet<D>& positions, std::vector<Real> times, bool addDisplacement = false);

  // A view whose displacement is not finite is passed by (the run's monitors report it).
  void observe(const StateView& state) override { take(state, false); }
  void end(const StateView& state) override { take(state, true); }

  // The snapshots taken (times, and positions particle-major) and the next time due.
  void saveState(StateArchive& archive) const override;
  void restoreState(const StateArchive& archive) override;

  const std::vector<Snapshot>& snapshots() const { return snapshots_; }

 private:
  void take(const StateView& state, bool last);

  const ParticleSet<D>& positions_;
  std::vector<Real> times_;
  bool addDisplacement_;
  std::size_t next_ = 0;
  std::vector<Snapshot> snapshots_;
};

extern template class PositionSnapshots<1>;
extern template class PositionSnapshots<2>;
extern template class PositionSnapshots<3>;

}  // namespace mfwave
