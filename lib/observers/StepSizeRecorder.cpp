#include "observers/StepSizeRecorder.hpp"

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

}  // namespace mfwave
