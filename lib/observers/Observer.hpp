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
};

}  // namespace mfwave
