#pragma once
// Records displacement or velocity components at chosen particles as time series.

#include "observers/Observer.hpp"
#include "observers/TimeSeries.hpp"

#include <string>
#include <vector>

namespace mfwave {

enum class ProbeQuantity { Displacement, Velocity };

struct Probe {
  std::string name;        // e.g. "centre"
  Index particle = 0;      // particle index in the particle set
  int component = 0;       // 0 = x, 1 = y, 2 = z
  ProbeQuantity quantity = ProbeQuantity::Velocity;
};

// The recorder's column names: "<name> v_z [m/s]", "<name> u [m]" for a scalar state. Throws
// InputError("probe[i].component") for a component outside [0, components), ("probe[i].particle")
// for a negative particle.
std::vector<std::string> probeColumnNames(const std::vector<Probe>& probes, int components, const std::string& timeUnit,
                                          const std::string& lengthUnit);

class ProbeRecorder : public Observer {
 public:
  // `components`: unknowns per particle in the state (dof = particle * components + component).
  // Units label the CSV header; mfwave itself works in any consistent units.
  ProbeRecorder(std::vector<Probe> probes, int components, std::string timeUnit = "s",
                std::string lengthUnit = "m");

  void observe(const StateView& state) override;
  const TimeSeries& series() const { return series_; }
  void saveState(StateArchive& archive) const override { series_.saveState(archive); }
  void restoreState(const StateArchive& archive) override { series_.restoreState(archive); }

 private:
  std::vector<Probe> probes_;
  int components_;
  TimeSeries series_;
  std::vector<Real> row_;
};

}  // namespace mfwave
