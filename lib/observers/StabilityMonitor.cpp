#include "observers/StabilityMonitor.hpp"

#include "core/Error.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace mfwave {

StabilityMonitor::StabilityMonitor(StabilityMonitorOptions options) : options_(options) {
  if (!(options_.growthFactor > 1)) throw InputError("stability.growth_factor", "must be greater than 1");
  if (options_.window < 1) throw InputError("stability.window", "must be at least 1");
  if (options_.components < 1) throw InputError("stability.components", "must be at least 1");
  if (!(options_.absoluteLimit > 0)) throw InputError("stability.absolute_limit", "must be positive");
  if (!(options_.oscillationThreshold > 0))
    throw InputError("stability.oscillation_threshold", "must be positive");
}

std::string StabilityMonitor::message(const StateView& state, const Vector& field, const char* name, Index worst,
                                      const std::string& why) const {
  std::ostringstream message;
  message.precision(6);
  const long particle = static_cast<long>(worst / options_.components);
  const long component = static_cast<long>(worst % options_.components);
  message << "numerical instability at step " << state.step << ", t = " << state.time << ": " << why << " in "
          << name << " of particle " << particle << " (component " << component << ", value " << field[worst]
          << ")";
  return message.str();
}

void StabilityMonitor::fail(const StateView& state, const Vector& field, const char* name, Index worst,
                            const std::string& why) const {
  throw InstabilityError(message(state, field, name, worst, why), state.step, state.time,
                         static_cast<long>(worst / options_.components));
}

Real StabilityMonitor::scan(const StateView& state, const Vector& field, const char* name, Index& worst) const {
  Real amplitude = 0;
  worst = 0;
  for (Index i = 0; i < field.size(); ++i) {
    const Real value = std::abs(field[i]);
    if (!std::isfinite(value)) {
      worst = i;
      fail(state, field, name, worst, "non-finite value");
    }
    if (value > amplitude) {
      amplitude = value;
      worst = i;
    }
  }
  if (amplitude > options_.absoluteLimit) {
    std::ostringstream why;
    why << "amplitude " << amplitude << " above the limit " << options_.absoluteLimit;
    fail(state, field, name, worst, why.str());
  }
  return amplitude;
}

bool StabilityMonitor::grewAgainstHistory(History& history, Real amplitude) const {
  const bool grew = history.reference > 0 && amplitude > options_.growthFactor * history.reference;
  // The reference is the largest amplitude seen at least `window` observations ago.
  history.amplitudes.push_back(amplitude);
  if (static_cast<long>(history.amplitudes.size()) > options_.window) {
    history.reference = std::max(history.reference, history.amplitudes.front());
    history.amplitudes.pop_front();
  }
  return grew;
}

bool StabilityMonitor::grewSinceQuiet(History& history, Real amplitude, bool judging) const {
  if (!judging) {
    history.quietReference = std::max(history.quietReference, amplitude);
    return false;
  }
  return history.quietReference > 0 && amplitude > options_.growthFactor * history.quietReference;
}

Real StabilityMonitor::oscillationRatio(const Vector& u) const {
  const Real scale = previous_.norm();
  if (scale == 0) return 0;
  return (u - 2 * previous_ + beforePrevious_).norm() / scale;
}

void StabilityMonitor::observe(const StateView& state) {
  Index worstU = 0, worstV = 0;
  const Real amplitudeU = scan(state, state.displacement, "displacement", worstU);
  const Real amplitudeV = scan(state, state.velocity, "velocity", worstV);
  const bool grewU = grewAgainstHistory(displacement_, amplitudeU);
  const bool grewV = grewAgainstHistory(velocity_, amplitudeV);
  ++observations_;
  if (observations_ >= 3) {
    lastRatio_ = oscillationRatio(state.displacement);
    if ((grewU || grewV) && lastRatio_ > options_.oscillationThreshold) {
      std::ostringstream why;
      why << "runaway growth of a grid-scale oscillation (amplitude grew more than " << options_.growthFactor
          << " times within " << options_.window << " observations; temporal second-difference ratio "
          << lastRatio_ << ", a mode at the time step's Nyquist limit: the step is too large for this operator)";
      if (grewU)
        fail(state, state.displacement, "displacement", worstU, why.str());
      else
        fail(state, state.velocity, "velocity", worstV, why.str());
    }
  }
  if (state.time >= options_.quietAfter) ++quietObservations_;
  const bool judging = quietObservations_ > options_.window;
  const bool quietU = grewSinceQuiet(displacement_, amplitudeU, judging);
  const bool quietV = grewSinceQuiet(velocity_, amplitudeV, judging);
  if (quietU && quietV && growthMessage_.empty()) {
    std::ostringstream why;
    why << "growth after the loads ended (displacement and velocity both above " << options_.growthFactor
        << " times their largest values until " << options_.window << " observations after t = "
        << options_.quietAfter << ", from when no load acts: a growing mode of the operator, a negative or complex "
        << "omega^2, or a step above the integrator's limit)";
    if (options_.stopGrowthAfterLoads) fail(state, state.displacement, "displacement", worstU, why.str());
    growthMessage_ = message(state, state.displacement, "displacement", worstU, why.str());
  }
  // Keep the last two displacements (swap buffers: one copy per observation).
  beforePrevious_.swap(previous_);
  previous_ = state.displacement;
}

}  // namespace mfwave
