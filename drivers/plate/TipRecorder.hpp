#pragma once
// Records the motion of the plate's free end: the displacement and velocity of the centroid of the
// tip column (the particles at the free end, across the thickness), so the bending of the plate
// is seen without the particle-scale shear of the end face. Works on either state the study's
// methods hand their observers, through a reader of the tip's (u, v) from a StateView.

#include "core/Error.hpp"
#include "observers/Observer.hpp"
#include "observers/TimeSeries.hpp"

#include <array>
#include <cmath>
#include <functional>
#include <utility>

namespace mfwave::plate {

class TipRecorder : public Observer {
 public:
  // (u_x, u_y, v_x, v_y) of the tip at the state.
  using Reader = std::function<std::array<Real, 4>(const StateView&)>;

  explicit TipRecorder(Reader reader)
      : reader_(std::move(reader)), series_("t [s]", {"u_x [m]", "u_y [m]", "v_x [m/s]", "v_y [m/s]"}) {}

  void observe(const StateView& state) override {
    if (series_.rows() > 0 && state.time <= series_.times().back()) return;  // end() after the last sample
    const std::array<Real, 4> tip = reader_(state);
    for (const Real value : tip)
      if (!std::isfinite(value))
        throw InstabilityError("the plate's tip has a non-finite displacement or velocity at t = " +
                                   std::to_string(state.time) + " (step " + std::to_string(state.step) + ")",
                               state.step, state.time, -1);
    series_.append(state.time, {tip[0], tip[1], tip[2], tip[3]});
  }
  void end(const StateView& state) override { observe(state); }

  const TimeSeries& series() const { return series_; }

 private:
  Reader reader_;
  TimeSeries series_;
};

}  // namespace mfwave::plate
