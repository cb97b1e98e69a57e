#pragma once
// Stops a run at the first sign of numerical instability and says where and when:
// the first non-finite value, or runaway growth of the largest displacement or velocity.

#include "observers/Observer.hpp"

#include <deque>
#include <limits>

namespace mfwave {

struct StabilityMonitorOptions {
  // Runaway growth: the amplitude max|u| (or max|v|) exceeds growthFactor times the largest
  // amplitude seen at least `window` observations earlier. Unstable explicit schemes grow
  // geometrically (by 1.3 a step at 1.01 times the central-difference limit), while physical
  // responses do not grow a thousandfold beyond their own history within a few dozen steps.
  // Growth slower than growthFactor^(1/window) per observation (1.15 with the defaults) is not
  // seen by this test: set absoluteLimit, or watch the energy, for slowly growing modes.
  Real growthFactor = 1e3;
  long window = 50;
  // Any amplitude above this bound stops the run at once (catches slow growth over long runs).
  Real absoluteLimit = std::numeric_limits<Real>::infinity();
  // Unknowns per particle, to report the particle (dof / components) and the component.
  int components = 1;
};

class StabilityMonitor : public Observer {
 public:
  explicit StabilityMonitor(StabilityMonitorOptions options = {});
  // Throws InstabilityError naming the step, time, particle and component.
  void observe(const StateView& state) override;

 private:
  void check(const StateView& state, const Vector& field, const char* name, std::deque<Real>& history,
             Real& reference);
  StabilityMonitorOptions options_;
  std::deque<Real> displacementHistory_, velocityHistory_;
  Real displacementReference_ = 0, velocityReference_ = 0;
};

}  // namespace mfwave
