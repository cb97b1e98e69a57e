#pragma once
// Progress of a long run on a terminal: step, simulated time, rate, time left. Silent when
// standard error is not a terminal (piped, CI) or when asked to be quiet, so logs stay clean.

#include "observers/Observer.hpp"

#include <chrono>
#include <iosfwd>

namespace mfwave {

class ProgressReporter : public Observer {
 public:
  // `particles` scales the rate to particle-steps per second. Enabled only if `enabled`, stderr is
  // a terminal and the CI environment variable is unset or "false".
  ProgressReporter(Real endTime, Index particles, bool enabled);
  // For tests: report to `out` unconditionally, at most every `minimumInterval` seconds.
  ProgressReporter(Real endTime, Index particles, std::ostream& out, double minimumInterval);

  void begin(const StateView& state) override;
  void observe(const StateView& state) override;
  void end(const StateView& state) override;
  // The start of the run (step, time) and the last state observed. The lines go to a terminal,
  // never to a file; after a restart the wall clock starts again, so the rate and the time left
  // count from the state the run was restored at (the last one observed before the checkpoint).
  void saveState(StateArchive& archive) const override;
  void restoreState(const StateArchive& archive) override;

  bool enabled() const { return out_ != nullptr; }
  // The line shown for `state` (also used by the tests).
  std::string line(const StateView& state, double elapsedSeconds) const;

 private:
  Real endTime_;
  Index particles_;
  std::ostream* out_ = nullptr;
  double minimumInterval_ = 0.25;
  Real startTime_ = 0;
  long startStep_ = 0;
  Real rateTime_ = 0;  // where the wall clock started: the rate and the time left count from here
  long rateStep_ = 0;
  Real lastTime_ = 0;  // the last state observed
  long lastStep_ = 0;
  std::chrono::steady_clock::time_point wallStart_, lastPrint_;
};

}  // namespace mfwave
