#pragma once
// What every case of the solid study shares, whatever its method: the probes' observer (a method
// gives the function that samples its field along each probe's direction) and the probes' CSV with
// the exact series beside them, scored against the reference.

#include "integrators/Integrator.hpp"
#include "observers/Observer.hpp"
#include "observers/TimeSeries.hpp"
#include "studies/solid/SolidStudy.hpp"

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace mfwave::solid {

// Records, at each sample, the values the method's sampler gives for every probe.
class SampledProbes final : public Observer {
 public:
  using Sampler = std::function<std::vector<Real>(const StateView&)>;
  SampledProbes(std::vector<std::string> names, Sampler sampler)
      : sampler_(std::move(sampler)), series_("t [s]", std::move(names)) {}
  void observe(const StateView& state) override { series_.append(state.time, sampler_(state)); }
  void end(const StateView& state) override {
    if (series_.times().empty() || series_.times().back() < state.time) observe(state);
  }
  void saveState(StateArchive& archive) const override { series_.saveState(archive); }
  void restoreState(const StateArchive& archive) override { series_.restoreState(archive); }
  const TimeSeries& series() const { return series_; }

 private:
  Sampler sampler_;
  TimeSeries series_;
};

template <int D>
std::vector<std::string> probeNames(const SolidPlan<D>& plan) {
  std::vector<std::string> names;
  for (const SolidProbe<D>& p : plan.probes) names.push_back(p.name);
  return names;
}

// Writes <folder>/<result.name>-probes.csv (each probe, and its exact series where the plan has a
// reference) and fills result's errors (relative L2, peak, arrival over the error window).
template <int D>
void writeAndScoreProbes(const SolidPlan<D>& plan, const TimeSeries& recorded, const std::string& folder,
                         SolidCaseResult& result);

}  // namespace mfwave::solid
