#include "io/run/RunSummary.hpp"

#include "io/run/BuildInfo.hpp"
#include "io/run/ShippedData.hpp"

#include "core/AtomicFile.hpp"
#include "core/CheckpointStore.hpp"
#include "core/Error.hpp"
#include "core/Interruption.hpp"

#include <nlohmann/json.hpp>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <ostream>

namespace mfwave {

void GrowingList::add(const std::string& entry) {
  if (!contains(entry)) entries_.push_back(entry);
}

void GrowingList::addAll(const std::vector<std::string>& entries) {
  for (const std::string& entry : entries) add(entry);
}

bool GrowingList::contains(const std::string& entry) const {
  return std::find(entries_.begin(), entries_.end(), entry) != entries_.end();
}

RunSummary::RunSummary() { files.add("scene.resolved.toml"); }

RunSummary::RunSummary(std::string programName, std::string sceneName, std::string methodName,
                       std::string integratorName)
    : RunSummary() {
  program = std::move(programName);
  scene = std::move(sceneName);
  method = std::move(methodName);
  integrator = std::move(integratorName);
}

double peakMemoryMiB() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // Linux reports kilobytes
}

double physicalMemoryMiB() {
  const long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && pageSize > 0 ? static_cast<double>(pages) * static_cast<double>(pageSize) / (1024.0 * 1024.0)
                                   : kUnknown;
}

double RunSummary::particleStepsPerSecond() const {
  return mfwave::particleStepsPerSecond(static_cast<double>(particles), static_cast<double>(steps), wallSeconds);
}

double CaseRecord::particleStepsPerSecond() const {
  if (!(loopSeconds > 0)) return kUnknown;
  const long stepped = resumedFromStep >= 0 ? steps - resumedFromStep : steps;  // in this process
  return mfwave::particleStepsPerSecond(static_cast<double>(particles), static_cast<double>(stepped), loopSeconds);
}

void RunSummary::addCase(CaseRecord record) {
  if (!record.primaryError.empty() &&
      std::none_of(record.errors.begin(), record.errors.end(),
                   [&](const auto& e) { return e.first == record.primaryError; }))
    throw Error("RunSummary::addCase: the primary error '" + record.primaryError + "' of case '" + record.name +
                "' is not one of its errors");
  if (std::isnan(record.peakMemoryMiB)) record.peakMemoryMiB = mfwave::peakMemoryMiB();
  if (std::isfinite(record.interruptedAt)) record.simulatedTime = record.interruptedAt;
  cases.push_back(std::move(record));
}

void RunSummary::totalsFromCases() {
  particles = 0;
  steps = 0;
  wallSeconds = 0;
  for (const CaseRecord& c : cases) {
    particles = std::max(particles, c.particles);
    steps += c.steps;
    if (std::isfinite(c.loopSeconds)) wallSeconds += c.loopSeconds;
  }
}

void RunSummary::totalsFromFirstCase() {
  if (cases.empty()) return;
  particles = cases.front().particles;
  timeStep = cases.front().timeStep;
  simulatedTime = cases.front().simulatedTime;
  steps = 0;
  wallSeconds = 0;
  for (const CaseRecord& c : cases) {
    steps += c.steps;
    wallSeconds += c.setupSeconds + c.loopSeconds;
  }
}

void RunSummary::finish() { peakMemoryMiB = mfwave::peakMemoryMiB(); }

void RunSummary::print(std::ostream& out) const {
  const auto flags = out.flags();
  const auto precision = out.precision();
  out << "== " << program << ": " << scene << '\n';
  out << "   method " << method << ", integrator " << integrator << '\n';
  out << "   particles " << particles;
  if (meanNeighbours > 0) out << ", mean neighbours " << std::setprecision(3) << meanNeighbours;
  out << '\n';
  out << "   steps " << steps << " of dt = " << std::setprecision(4) << timeStep << " to t = " << simulatedTime << '\n';
  out << "   wall time " << std::setprecision(3) << wallSeconds << " s, " << std::scientific << std::setprecision(2)
      << particleStepsPerSecond() << " particle-steps/s, peak memory " << std::defaultfloat << std::setprecision(4)
      << peakMemoryMiB << " MiB\n";
  for (const auto& [name, value] : errors) out << "   error " << name << " = " << std::setprecision(4) << value << '\n';
  for (const auto& [name, value] : figures) out << "   " << name << " = " << std::setprecision(4) << value << '\n';
  for (const auto& note : notes) out << "   note: " << note << '\n';
  out.flags(flags);
  out.precision(precision);
}

void RunSummary::writeJson(const std::string& path) const {
  nlohmann::ordered_json j;
  j["program"] = program;
  j["mfwave_version"] = mfwaveVersion();  // which build made the result
  j["git_revision"] = mfwaveGitRevision();
  j["scene"] = scene;
  j["method"] = method;
  j["integrator"] = integrator;
  j["particles"] = particles;
  j["mean_neighbours"] = meanNeighbours;
  j["steps"] = steps;
  j["time_step"] = timeStep;
  j["simulated_time"] = simulatedTime;
  j["wall_seconds"] = wallSeconds;
  j["particle_steps_per_second"] = particleStepsPerSecond();
  j["peak_memory_mib"] = peakMemoryMiB;
  if (interruptionRequested()) j["interrupted"] = interruptionSignalName();  // only then: a run that ended early
  j["errors"] = nlohmann::ordered_json::object();
  for (const auto& [name, value] : errors) j["errors"][name] = value;
  j["figures"] = nlohmann::ordered_json::object();
  for (const auto& [name, value] : figures) j["figures"][name] = value;
  j["notes"] = notes.entries();
  if (!cases.empty()) {
    // nlohmann writes a non-finite number as null, which is what an unknown value should read as.
    j["cases"] = nlohmann::ordered_json::array();
    for (const CaseRecord& c : cases) {
      nlohmann::ordered_json k;
      k["case"] = c.name;
      k["particles"] = c.particles;
      k["steps"] = c.steps;
      k["dt"] = c.timeStep;
      k["stable_dt"] = c.stableTimeStep;
      k["simulated_time"] = c.simulatedTime;
      if (std::isfinite(c.interruptedAt)) k["interrupted_at"] = c.interruptedAt;
      if (c.resumedFromStep >= 0) k["resumed_from_step"] = c.resumedFromStep;
      k["setup_seconds"] = c.setupSeconds;
      k["loop_seconds"] = c.loopSeconds;
      k["particle_steps_per_second"] = c.particleStepsPerSecond();
      k["peak_memory_mib"] = c.peakMemoryMiB;
      k["errors"] = nlohmann::ordered_json::object();
      for (const auto& [name, value] : c.errors) k["errors"][name] = value;
      if (c.primaryError.empty()) {
        k["primary_error"] = nullptr;
        k["primary_error_value"] = nullptr;
      } else {
        k["primary_error"] = c.primaryError;
        for (const auto& [name, value] : c.errors)
          if (name == c.primaryError) k["primary_error_value"] = value;
      }
      j["cases"].push_back(k);
    }
  }
  std::vector<std::string> written = files.entries();
  if (!files.contains("summary.json")) written.push_back("summary.json");
  j["files"] = written;
  AtomicFile file(path);
  file.stream() << j.dump(2) << '\n';
  file.commit();
}

void RunSummary::conclude(const std::string& folder, std::ostream* terminal) {
  // An interrupted case: the run's simulated time is how far that case got, whatever the driver set.
  for (const CaseRecord& c : cases)
    if (std::isfinite(c.interruptedAt)) simulatedTime = c.interruptedAt;
  if (interruptionRequested())
    notes.add(std::string("interrupted by ") + interruptionSignalName() +
              ": the run stopped early; steps, simulated time, errors and figures are those of the part that ran, "
              "and the cases after the one that was stepping were not run");
  if (const CheckpointStore* store = checkpointStore())
    for (const std::string& note : store->notes()) notes.add(note);
  finish();
  writeJson(folder + "/summary.json");
  if (!terminal) return;
  print(*terminal);
  // How to draw what the run wrote, from wherever the program's plot script is (installed or the
  // source tree); on the terminal only, as its path depends on the machine.
  if (const std::optional<std::string> script = findPlotScript(program))
    *terminal << "   plot: /usr/bin/python3 " << *script << ' ' << folder << '\n';
}

}  // namespace mfwave
