#include "io/run/RunSummary.hpp"

#include "core/AtomicFile.hpp"

#include <nlohmann/json.hpp>
#include <sys/resource.h>

#include <iomanip>
#include <ostream>

namespace mfwave {

double peakMemoryMiB() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // Linux reports kilobytes
}

double RunSummary::particleStepsPerSecond() const {
  return wallSeconds > 0 ? static_cast<double>(particles) * static_cast<double>(steps) / wallSeconds : 0;
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
  j["notes"] = notes;
  j["files"] = files;
  AtomicFile file(path);
  file.stream() << j.dump(2) << '\n';
  file.commit();
}

}  // namespace mfwave
