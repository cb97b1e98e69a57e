#include "observers/TimeLoop.hpp"

#include "core/CheckpointStore.hpp"
#include "core/Error.hpp"
#include "core/Interruption.hpp"
#include "core/Stopwatch.hpp"

#include <cmath>
#include <optional>
#include <string>

namespace mfwave {

void TimeLoop::add(Observer& observer, long every) {
  if (every < 1) throw InputError("output_every", "must be at least 1, got " + std::to_string(every));
  observers_.push_back({&observer, every});
}

StateArchive TimeLoop::save(const Integrator& integrator, long firstStep, Real startTime) const {
  StateArchive archive;
  StateArchive loop = archive.section("loop");
  loop.put("start", std::vector<Real>{static_cast<Real>(firstStep), startTime, static_cast<Real>(observers_.size())});
  StateArchive integratorPart = archive.section("integrator");
  integrator.saveState(integratorPart);
  for (std::size_t i = 0; i < observers_.size(); ++i) {
    StateArchive part = archive.section("observer" + std::to_string(i));
    observers_[i].observer->saveState(part);
  }
  return archive;
}

void TimeLoop::restore(Integrator& integrator, const StateArchive& archive, long& firstStep, Real& startTime) {
  const std::vector<Real>& start = archive.section("loop").get("start");
  if (start.size() != 3 || start[2] != static_cast<Real>(observers_.size()))
    throw InputError("--restart", "the checkpoint's time loop had another set of observers than this run's (" +
                                      std::to_string(observers_.size()) + ")");
  firstStep = static_cast<long>(start[0]);
  startTime = start[1];
  integrator.restoreState(archive.section("integrator"));
  for (std::size_t i = 0; i < observers_.size(); ++i)
    observers_[i].observer->restoreState(archive.section("observer" + std::to_string(i)));
}

RunStatistics TimeLoop::run(Integrator& integrator, Real endTime) {
  if (!std::isfinite(endTime)) throw InputError("end_time", "must be finite");
  CheckpointStore* store = checkpointStore();
  if (store && store->sharedByRanks() && store->everySeconds() > 0 && !agree_)
    throw InputError(store->settingName(), "a wall-clock checkpoint period on MPI ranks needs a time loop that "
                                           "agrees its steps across them; give a step count");
  const int loopIndex = store ? store->claimLoop() : -1;
  const std::optional<CheckpointPoint> resume = store ? store->resumePoint(loopIndex) : std::nullopt;
  RunStatistics stats;
  stats.startTime = integrator.time();
  long firstStep = integrator.stepCount();
  if (resume) {
    restore(integrator, resume->archive, firstStep, stats.startTime);
    stats.resumedFromStep = integrator.stepCount();
  } else {
    for (auto& entry : observers_) entry.observer->begin(integrator.state());
    if (store) {
      // A trial save: a part that cannot be checkpointed is refused now, not after hours of stepping.
      try {
        (void)save(integrator, firstStep, stats.startTime);
      } catch (const InputError&) {
        throw;
      } catch (const Error& e) {
        throw InputError(store->settingName(), std::string("this run cannot be checkpointed: ") + e.what());
      }
    }
  }
  const Stopwatch wall;
  const InterruptionGuard guard;
  Stopwatch sinceCheckpoint;
  long lastCheckpoint = resume ? integrator.stepCount() : -1;
  const auto writeCheckpoint = [&] {
    store->write(loopIndex, integrator.stepCount(), integrator.time(), save(integrator, firstStep, stats.startTime));
    lastCheckpoint = integrator.stepCount();
    sinceCheckpoint.restart();
  };

  // Half a step of slack so round-off in t never adds or drops a fixed step.
  const auto beforeTheEnd = [&] { return integrator.time() < endTime - 0.5 * integrator.stepSize(); };
  // On ranks the stop and the wall-clock checkpoint are agreed at the step boundary (agree_).
  bool wallClockDue = false;
  const auto stopRequested = [&] {
    const bool due = store && store->everySeconds() > 0 && sinceCheckpoint.seconds() >= store->everySeconds();
    if (!agree_) {
      wallClockDue = due;
      return interruptionRequested();
    }
    int flags[2] = {interruptionSignal(), due ? 1 : 0};
    agree_(flags, 2);
    requestInterruption(flags[0]);
    wallClockDue = flags[1] != 0;
    return flags[0] != 0;
  };
  while (beforeTheEnd() && !stopRequested()) {
    // Due after the last step (the state every observer has seen), written before the next.
    if (wallClockDue && lastCheckpoint != integrator.stepCount()) writeCheckpoint();
    integrator.step();
    const long n = integrator.stepCount() - firstStep;
    for (auto& entry : observers_)
      if (n % entry.every == 0) entry.observer->observe(integrator.state());
    if (store && store->everySteps() > 0 && n % store->everySteps() == 0) writeCheckpoint();
  }
  // The state the loop ends in (its end, or where a signal stopped it), before the closing
  // observations: a restart from it observes and closes exactly as this run does.
  if (store && lastCheckpoint != integrator.stepCount()) writeCheckpoint();
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
