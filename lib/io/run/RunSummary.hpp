#pragma once
// What every run reports at the end, on the terminal and as summary.json in its output folder:
// size, cost and, when a reference exists, the error against it.

#include "core/Stopwatch.hpp"
#include "core/Types.hpp"

#include <iosfwd>
#include <string>
#include <utility>
#include <vector>

namespace mfwave {

// A list that only grows: entries are appended in order, a name already listed is not listed
// again, and nothing removes, reorders or reassigns entries. The summary's files and notes are
// such lists, so a driver cannot lose an entry by building the list a second time (the plate
// study once dropped modes.csv that way), and merging the notes of several cases needs no code.
class GrowingList {
 public:
  GrowingList() = default;
  GrowingList(const GrowingList&) = default;
  GrowingList& operator=(const GrowingList&) = delete;  // assigning would drop what was listed

  void add(const std::string& entry);
  void addAll(const std::vector<std::string>& entries);
  bool contains(const std::string& entry) const;
  const std::vector<std::string>& entries() const { return entries_; }
  std::size_t size() const { return entries_.size(); }
  bool empty() const { return entries_.empty(); }
  auto begin() const { return entries_.begin(); }
  auto end() const { return entries_.end(); }

 private:
  std::vector<std::string> entries_;
};

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
  GrowingList notes;  // e.g. why no PNG was made
  // Outputs written, relative to the output folder. scene.resolved.toml (written by
  // prepareOutputFolder) is listed from the start and summary.json is listed last by writeJson.
  GrowingList files;

  RunSummary();

  double particleStepsPerSecond() const;
  // Reads the peak resident memory of this process.
  void finish();
  void print(std::ostream& out) const;
  // Writes the summary as JSON (atomically).
  void writeJson(const std::string& path) const;
  // The notes and files of every case of a multi-case study, in case order (each listed once):
  // `Case` has `notes` and `files`, string lists.
  template <class Case>
  void addCases(const std::vector<Case>& cases) {
    for (const Case& c : cases) {
      notes.addAll(c.notes);
      files.addAll(c.files);
    }
  }
  // The end every driver shares: finish(), "<folder>/summary.json", and the terminal summary
  // on `terminal` when it is given.
  void conclude(const std::string& folder, std::ostream* terminal);
};

// Peak resident set size of this process so far, in MiB (getrusage).
double peakMemoryMiB();

}  // namespace mfwave
