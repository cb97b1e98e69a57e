#pragma once
// What every case of the solid study shares, whatever its method: the probes' observer (a method
// gives the function that samples its field along each probe's direction) and the probes' CSV with
// the exact series beside them, scored against the reference.

#include "core/Error.hpp"
#include "integrators/Integrator.hpp"
#include "io/run/RunSummary.hpp"
#include "methods/collocation/ShapeFunctions.hpp"
#include "observers/Observer.hpp"
#include "observers/TimeLoop.hpp"
#include "observers/TimeSeries.hpp"
#include "studies/solid/SolidStudy.hpp"

#include <algorithm>
#include <functional>
#include <sstream>
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

// A case's result before it runs: named <prefix>_<spacing>, its method and kind of cells.
inline SolidCaseResult startCase(const std::string& prefix, const std::string& method, const std::string& cells,
                                 Real spacing) {
  SolidCaseResult result;
  std::ostringstream name;
  name << prefix << '_' << spacing;
  result.name = name.str();
  result.method = method;
  result.cells = cells;
  result.spacing = spacing;
  return result;
}

// What the loop measured: its wall time and steps, and the process's peak memory so far.
inline void recordRun(SolidCaseResult& result, const RunStatistics& stats) {
  result.runSeconds = stats.wallSeconds;
  result.steps = stats.steps;
  result.peakMiB = peakMemoryMiB();
}

// Runs `loop` to `endTime`. On a blow-up the probes recorded up to the stop are written (and scored)
// first, then the InstabilityError is thrown again with `where(particle)` appended (the method's
// word for the state's particle: a node, a particle's start), when the particle is one it knows
// (where returns "" otherwise: the error then goes on as it came).
template <int D, class Where>
RunStatistics runCase(TimeLoop& loop, Integrator& integrator, Real endTime, const SolidPlan<D>& plan,
                      const SampledProbes& probes, const std::string& folder, SolidCaseResult& result, Where where) {
  try {
    return loop.run(integrator, endTime);
  } catch (const InstabilityError& e) {
    writeAndScoreProbes(plan, probes.series(), folder, result);
    const std::string place = e.particle() < 0 ? std::string() : where(e.particle());
    if (place.empty()) throw;
    throw InstabilityError(std::string(e.what()) + " [" + place + "; " + result.name +
                               "-probes.csv holds the probes up to the stop]",
                           e.step(), e.time(), e.particle());
  }
}

// The share of a surface point's tributary piece of surface (of size `spacing` along the surface) that
// lies within `radius` of a load's centre, at `distance` from it: clamp((r - d) / s + 1/2, 0, 1). On
// points s apart along a line it is the trapezoid rule's 1 inside, 1/2 at an edge on a point and 0
// outside, and wherever the edges fall the total is the load's to O(s^2).
inline Real surfaceLoadShare(Real radius, Real distance, Real spacing) {
  return std::clamp((radius - distance) / spacing + 0.5, 0.0, 1.0);
}

// Each probe's row over the D components of a method's nodes: sum_J psi_J(x_p) (d_p . u_J) for shape
// functions psi (RK collocation's own, or the particle methods' interpolation), times `scale`.
template <int D>
std::vector<std::vector<std::pair<Index, Real>>> shapeFunctionRows(const ShapeFunctions<D>& shapes,
                                                                   const std::vector<SolidProbe<D>>& probes, Real scale) {
  std::vector<std::vector<std::pair<Index, Real>>> rows;
  ShapeFunctionValues<D> values;
  for (const SolidProbe<D>& p : probes) {
    shapes.evaluate(p.position, 0, values);
    std::vector<std::pair<Index, Real>> row;
    for (Index k = 0; k < values.size(); ++k)
      for (int c = 0; c < D; ++c)
        if (p.direction[c] != 0)
          row.emplace_back(D * values.nodes[static_cast<std::size_t>(k)] + c,
                           p.direction[c] * values.value[static_cast<std::size_t>(k)] * scale);
    rows.push_back(std::move(row));
  }
  return rows;
}

// The sampler of probes that are fixed linear combinations of the state's entries: probe i reads
// sum_k w_k field[dof_k] over rows[i], the velocity where velocity[i], else the displacement.
inline SampledProbes::Sampler rowSampler(std::vector<std::vector<std::pair<Index, Real>>> rows, std::vector<bool> velocity) {
  return [rows = std::move(rows), velocity = std::move(velocity)](const StateView& state) {
    std::vector<Real> values;
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const Vector& field = velocity[i] ? state.velocity : state.displacement;
      Real value = 0;
      for (const auto& [dof, w] : rows[i]) value += w * field[dof];
      values.push_back(value);
    }
    return values;
  };
}

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
