#include "observers/ProbeRecorder.hpp"

#include "core/Error.hpp"

namespace mfwave {

std::vector<std::string> probeColumnNames(const std::vector<Probe>& probes, int components, const std::string& timeUnit,
                                     const std::string& lengthUnit) {
  static const char* axis = "xyz";
  std::vector<std::string> names;
  for (std::size_t p = 0; p < probes.size(); ++p) {
    const Probe& probe = probes[p];
    const std::string key = "probe[" + std::to_string(p) + "]";
    if (probe.component < 0 || probe.component >= components || probe.component > 2)
      throw InputError(key + ".component", "must lie in [0, " + std::to_string(components - 1) + "]");
    if (probe.particle < 0) throw InputError(key + ".particle", "must not be negative");
    const bool velocity = probe.quantity == ProbeQuantity::Velocity;
    // A scalar state (one component) has no axis to name.
    const std::string symbol = std::string(velocity ? " v" : " u") +
                               (components > 1 ? std::string("_") + axis[probe.component] : std::string());
    names.push_back(probe.name + symbol + " [" + lengthUnit + (velocity ? "/" + timeUnit : std::string()) + "]");
  }
  return names;
}

ProbeRecorder::ProbeRecorder(std::vector<Probe> probes, int components, std::string timeUnit,
                             std::string lengthUnit)
    : probes_(std::move(probes)),
      components_(components),
      series_("time [" + timeUnit + "]", probeColumnNames(probes_, components, timeUnit, lengthUnit)),
      row_(probes_.size()) {
  if (components < 1) throw InputError("components", "must be at least 1");
}

void ProbeRecorder::observe(const StateView& state) {
  for (std::size_t p = 0; p < probes_.size(); ++p) {
    const Probe& probe = probes_[p];
    const Index dof = probe.particle * components_ + probe.component;
    const Vector& field = probe.quantity == ProbeQuantity::Velocity ? state.velocity : state.displacement;
    if (dof >= field.size())
      throw InputError("probe[" + std::to_string(p) + "].particle",
                       "particle " + std::to_string(probe.particle) + " does not exist (the state has " +
                           std::to_string(field.size() / components_) + " particles)");
    row_[p] = field[dof];
  }
  series_.append(state.time, row_);
}

}  // namespace mfwave
