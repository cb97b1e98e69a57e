#include "observers/TimeLoop.hpp"

#include "core/Error.hpp"
#include "core/Interruption.hpp"
#include "core/Stopwatch.hpp"

#include <cmath>
#include <string>

namespace mfwave {

void TimeLoop::add(Observer& observer, long every) {
  if (every < 1) throw InputError("output_every", "must be at least 1, got " + std::to_string(every));
  observers_.push_back({&observer, every});
}

RunStatistics TimeLoop::run(Integrator& integrator, Real endTime) {
  if (!std::isfinite(endTime)) throw InputError("end_time", "must be finite");
  const Stopwatch wall;
  const InterruptionGuard guard;
  RunStatistics stats;
  stats.startTime = integrator.time();
  const long firstStep = integrator.stepCount();
  for (auto& entry : observers_) entry.observer->begin(integrator.state());

  // Half a step of slack so round-off in t never adds or drops a fixed step.
  const auto beforeTheEnd = [&] { return integrator.time() < endTime - 0.5 * integrator.stepSize(); };
  while (beforeTheEnd() && !interruptionRequested()) {
    integrator.step();
    const long n = integrator.stepCount() - firstStep;
    for (auto& entry : observers_)
      if (n % entry.every == 0) entry.observer->observe(integrator.state());
  }
  const long taken = integrator.stepCount() - firstStep;
  for (auto& entry : observers_) {
    if (taken % entry.every != 0) entry.observer->observe(integrator.state());
    entry.observer->end(integrator.state());
  }
  stats.steps = taken;
  stats.interrupted = interruptionRequested() && beforeTheEnd();
  stats.endTime = integrator.time();
  stats.wallSeconds = wall.seconds();
  return stats;
}

}  // namespace mfwave
