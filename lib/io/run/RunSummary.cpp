#include "io/run/RunSummary.hpp"

#include "core/AtomicFile.hpp"

#include <nlohmann/json.hpp>
#include <sys/resource.h>

#include <algorithm>
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

double peakMemoryMiB() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // Linux reports kilobytes
}

double RunSummary::particleStepsPerSecond() const {
  return mfwave::particleStepsPerSecond(static_cast<double>(particles), static_cast<double>(steps), wallSeconds);
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
  j["errors"] = nlohmann::ordered_json::object();
  for (const auto& [name, value] : errors) j["errors"][name] = value;
  j["figures"] = nlohmann::ordered_json::object();
  for (const auto& [name, value] : figures) j["figures"][name] = value;
  j["notes"] = notes.entries();
  std::vector<std::string> written = files.entries();
  if (!files.contains("summary.json")) written.push_back("summary.json");
  j["files"] = written;
  AtomicFile file(path);
  file.stream() << j.dump(2) << '\n';
  file.commit();
}

void RunSummary::conclude(const std::string& folder, std::ostream* terminal) {
  finish();
  writeJson(folder + "/summary.json");
  if (terminal) print(*terminal);
}

}  // namespace mfwave
