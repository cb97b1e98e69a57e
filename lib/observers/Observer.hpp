#pragma once
// Observers read the state every n steps and record or check it; they never change it.

#include "integrators/Integrator.hpp"

namespace mfwave {

class Observer {
 public:
  virtual ~Observer() = default;
  // Called once with the initial state, before the first step.
  virtual void begin(const StateView& state) { observe(state); }
  // Called every n steps (n chosen when the observer is added to the TimeLoop).
  virtual void observe(const StateView& state) = 0;
  // Called once with the final state, after the last step (also when it is not a multiple of n).
  virtual void end(const StateView& state) { (void)state; }

  // Checkpoints (issue 20): what the observer has gathered (buffers, running maxima, reference
  // values from begin()), so that a run restored from a checkpoint writes the same outputs as one
  // that never stopped. On a restart the TimeLoop calls restoreState in place of begin(). The
  // defaults throw Error naming the observer's type: one that gathers nothing says so by
  // overriding both with nothing.
  virtual void saveState(StateArchive& archive) const;
  virtual void restoreState(const StateArchive& archive);
};

// For observers that gather nothing between steps (they check, print or write each state).
class StatelessObserver : public Observer {
 public:
  void saveState(StateArchive& archive) const override { (void)archive; }
  void restoreState(const StateArchive& archive) override { (void)archive; }
};

}  // namespace mfwave
