#pragma once
// The loop every multi-case study shares. A case's result derives from StudyCase: it fills its
// canonical record (what it cost, how accurate it was) as it runs, and lists the files it wrote and
// its notes, so that the summary takes every case whole (RunSummary::addCases,
// RunSummary::mergeNotesAndFiles) and no driver copies a field into a record.

#include "core/Interruption.hpp"
#include "io/run/RunSummary.hpp"
#include "observers/TimeLoop.hpp"

#include <iostream>
#include <string>
#include <type_traits>
#include <vector>

namespace mfwave {

struct StudyCase {
  CaseRecord record;
  std::vector<std::string> files;  // written, relative to the output folder
  std::vector<std::string> notes;  // for the summary (stability.allow_growth, fallbacks, ...)

  // The time loop's share of the record: the steps it took, its seconds and, when SIGINT or SIGTERM
  // ended it early, the time it had reached.
  void recordLoop(const RunStatistics& loop) {
    record.steps = loop.steps;
    record.loopSeconds = loop.wallSeconds;
    if (loop.interrupted) record.interruptedAt = loop.endTime;
    record.resumedFromStep = loop.resumedFromStep;
  }
};

// Runs `run(settings)` for each entry of `plan` in order and returns the results; with `progress`,
// says on stderr when each case is done, by its record's name, particles and steps. After SIGINT or
// SIGTERM (core/Interruption) the case that was stepping ends early and no further case starts:
// the results hold the cases run so far. Under mpirun, `agree` (TimeLoop::Agreement) makes the
// ranks agree after each case whether to stop, so a signal that reached only some of them still
// stops all of them before the same case.
template <class Settings, class Run>
auto runCases(const std::vector<Settings>& plan, Run&& run, bool progress, const TimeLoop::Agreement& agree = {}) {
  std::vector<std::decay_t<std::invoke_result_t<Run&, const Settings&>>> results;
  results.reserve(plan.size());
  for (const Settings& settings : plan) {
    results.push_back(run(settings));
    if (progress) {
      const CaseRecord& r = results.back().record;
      std::cerr << "  done " << r.name << " (" << r.particles << " particles, " << r.steps << " steps)\n";
    }
    if (agree) {
      int signal = interruptionSignal();
      agree(&signal, 1);
      requestInterruption(signal);
    }
    if (interruptionRequested()) break;
  }
  return results;
}

}  // namespace mfwave
