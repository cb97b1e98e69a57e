#pragma once
// What every run reports at the end, on the terminal and as summary.json in its output folder:
// size, cost and, when a reference exists, the error against it.

#include "core/Types.hpp"

#include <iosfwd>
#include <string>
#include <utility>
#include <vector>

namespace mfwave {

struct RunSummary {
  std::string program;
  std::string scene;           // scene name (or study name)
  std::string method;
  std::string integrator;
  Index particles = 0;
  Real meanNeighbours = 0;     // 0 when the method has no neighbour list
  long steps = 0;
  Real timeStep = 0;
  Real simulatedTime = 0;
  double wallSeconds = 0;
  double peakMemoryMiB = 0;    // filled by finish()
  // Named error measures against the reference, e.g. {"relative_l2_centre", 0.05}.
  std::vector<std::pair<std::string, Real>> errors;
  // Other figures worth a line (energy drift, stable step, ...).
  std::vector<std::pair<std::string, Real>> figures;
  std::vector<std::string> notes;   // e.g. why no PNG was made
  std::vector<std::string> files;   // outputs written, relative to the output folder

  double particleStepsPerSecond() const;
  // Reads the peak resident memory of this process.
  void finish();
  void print(std::ostream& out) const;
  // Writes the summary as JSON (atomically).
  void writeJson(const std::string& path) const;
};

// Peak resident set size of this process so far, in MiB (getrusage).
double peakMemoryMiB();

}  // namespace mfwave
