#pragma once
// What every run reports at the end, on the terminal and as summary.json in its output folder:
// size, cost and, when a reference exists, the error against it.

#include "core/Stopwatch.hpp"
#include "core/Types.hpp"

#include <iosfwd>
#include <limits>
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

// One case of a study in the layout every tool reads (summary.json's "cases", in run order): what
// it cost and how accurate it was, whatever the driver. Times are split so that a speed is always
// the time loop's: setup (particles, neighbours, assembly, stable-step estimate) and loop (the
// steps and the observers). Unknown values stay NaN and are written as null.
inline constexpr Real kUnknown = std::numeric_limits<Real>::quiet_NaN();

struct CaseRecord {
  std::string name;                 // e.g. "central_difference, 64 cells", "dx = 0.5, galerkin"
  Index particles = 0;
  long steps = 0;
  Real timeStep = kUnknown;             // the step used (the last one when it varies)
  Real stableTimeStep = kUnknown;       // the limit the step is a fraction of
  Real simulatedTime = kUnknown;
  double setupSeconds = kUnknown;
  double loopSeconds = kUnknown;
  // Named errors against the reference; `primaryError` names the one a tool ranks the case by.
  std::vector<std::pair<std::string, Real>> errors;
  std::string primaryError;
  // The time the case had reached when SIGINT or SIGTERM ended it early (StudyCase::recordLoop);
  // unknown for a case that ran to its end. addCase then takes it as the simulated time.
  Real interruptedAt = kUnknown;
  // The step this case went on from when it was restored from a checkpoint (-1: it ran from its
  // start in this process). Its loop seconds are this process's only, and so is its throughput.
  long resumedFromStep = -1;
  double peakMemoryMiB = kUnknown;      // the process's peak when the case ended (cases run smallest
                                        // first); addCase fills in the peak so far if unknown

  double particleStepsPerSecond() const;  // particles x steps / loop seconds
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
  // Every case in the canonical layout (empty: no "cases" in summary.json).
  std::vector<CaseRecord> cases;

  RunSummary();
  // What ran: the program, the scene (or study) name, the method and the integrator.
  RunSummary(std::string programName, std::string sceneName, std::string methodName, std::string integratorName);

  // Appends `record` (with the process's peak memory so far if it has none); checks that its primary error is one
  // of its errors (a programming error otherwise).
  void addCase(CaseRecord record);
  // The run's totals from its cases, for a study whose cases run one after another: particles of
  // the largest case, steps and (loop) wall seconds summed over all cases.
  void totalsFromCases();
  // The totals of a study whose first case is its main one: particles, dt and simulated time of
  // the first case, steps and wall seconds (set-up and loop) summed over all cases.
  void totalsFromFirstCase();
  // The record of every case of a study (each `Case` holds its `record` from the start), in run
  // order.
  template <class Case>
  void addCases(const std::vector<Case>& results) {
    for (const Case& c : results) addCase(c.record);
  }

  double particleStepsPerSecond() const;
  // Reads the peak resident memory of this process.
  void finish();
  void print(std::ostream& out) const;
  // Writes the summary as JSON (atomically).
  void writeJson(const std::string& path) const;
  // The notes and files of every case of a multi-case study, in case order (each listed once):
  // `Case` has `notes` and `files`, string lists.
  template <class Case>
  void mergeNotesAndFiles(const std::vector<Case>& results) {
    for (const Case& c : results) {
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
// The machine's physical memory in MiB (unknown if the system does not say): what a run that
// would need more is refused against, before it allocates.
double physicalMemoryMiB();

}  // namespace mfwave
