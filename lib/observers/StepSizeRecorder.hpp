#pragma once
// The steps an integrator took, as its observers see them (StateView::dt): the smallest, the
// largest and the last. An adaptive integrator or a step rule that follows the state (the
// updated-Lagrangian SPH's criteria) can shrink its step by orders of magnitude before a blow-up;
// the smallest step says so. Add it to the TimeLoop at every step.

#include "observers/Observer.hpp"

#include <limits>

namespace mfwave {

class StepSizeRecorder : public Observer {
 public:
  // The initial state has taken no step: begin() records nothing.
  void begin(const StateView& state) override { lastStep_ = state.step; }
  void observe(const StateView& state) override;
  void end(const StateView& state) override { observe(state); }

  // The last step seen, the count and the smallest, largest and last step.
  void saveState(StateArchive& archive) const override;
  void restoreState(const StateArchive& archive) override;

  long steps() const { return steps_; }
  Real smallest() const { return smallest_; }  // infinity before the first step
  Real largest() const { return largest_; }    // 0 before the first step
  Real last() const { return last_; }

 private:
  long lastStep_ = -1;
  long steps_ = 0;
  Real smallest_ = std::numeric_limits<Real>::infinity();
  Real largest_ = 0;
  Real last_ = 0;
};

}  // namespace mfwave
