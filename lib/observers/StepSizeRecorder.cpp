#include "observers/StepSizeRecorder.hpp"

#include "core/Error.hpp"

#include <algorithm>

namespace mfwave {

void StepSizeRecorder::observe(const StateView& state) {
  if (state.step <= lastStep_) return;  // seen (end() right after the last step's observe())
  lastStep_ = state.step;
  ++steps_;
  last_ = state.dt;
  smallest_ = std::min(smallest_, state.dt);
  largest_ = std::max(largest_, state.dt);
}

void StepSizeRecorder::saveState(StateArchive& archive) const {
  archive.put("steps", std::vector<Real>{static_cast<Real>(lastStep_), static_cast<Real>(steps_), smallest_, largest_,
                                         last_});
}

void StepSizeRecorder::restoreState(const StateArchive& archive) {
  const std::vector<Real>& steps = archive.numbers("steps", 5);
  lastStep_ = static_cast<long>(steps[0]);
  steps_ = static_cast<long>(steps[1]);
  smallest_ = steps[2];
  largest_ = steps[3];
  last_ = steps[4];
}

}  // namespace mfwave
