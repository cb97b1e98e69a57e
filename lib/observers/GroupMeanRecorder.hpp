#pragma once
// Records the mean displacement and velocity of a group of particles (the tip column of a plate,
// the particles of a face, one body of several), component by component, from a particle view:
// `components` values per particle in StateView::displacement and ::velocity, as a second-order
// integrator hands them and a ViewAdapter (SolidStateAdapter) forms them for a first-order one.
// The mean over a group sees the motion of a part (the bending of a plate) without the particle-
// scale motion inside it. Works for every method that offers such a view.

#include "core/Types.hpp"
#include "observers/Observer.hpp"
#include "observers/TimeSeries.hpp"

#include <string>
#include <vector>

namespace mfwave {

class GroupMeanRecorder : public Observer {
 public:
  // Columns "u_x [m]", "u_y [m]", ..., "v_x [m/s]", ...; `group` names it in messages.
  GroupMeanRecorder(std::string group, std::vector<Index> members, int components);

  // A non-finite mean stops the run (InstabilityError naming the group, the step and the time).
  void observe(const StateView& state) override;
  // The final state, unless it was the last one observed.
  void end(const StateView& state) override;
  // The rows so far.
  void saveState(StateArchive& archive) const override { series_.saveState(archive); }
  void restoreState(const StateArchive& archive) override { series_.restoreState(archive); }

  const TimeSeries& series() const { return series_; }

 private:
  std::string group_;
  std::vector<Index> members_;
  int components_;
  TimeSeries series_;
};

}  // namespace mfwave
