#include "observers/StabilityMonitor.hpp"

#include "core/Error.hpp"

#include <cmath>
#include <sstream>

namespace mfwave {

StabilityMonitor::StabilityMonitor(StabilityMonitorOptions options) : options_(options) {
  if (!(options_.growthFactor > 1)) throw InputError("stability.growth_factor", "must be greater than 1");
  if (options_.window < 1) throw InputError("stability.window", "must be at least 1");
  if (options_.components < 1) throw InputError("stability.components", "must be at least 1");
  if (!(options_.absoluteLimit > 0)) throw InputError("stability.absolute_limit", "must be positive");
}

void StabilityMonitor::observe(const StateView& state) {
  check(state, state.displacement, "displacement", displacementHistory_, displacementReference_);
  check(state, state.velocity, "velocity", velocityHistory_, velocityReference_);
}

void StabilityMonitor::check(const StateView& state, const Vector& field, const char* name,
                             std::deque<Real>& history, Real& reference) {
  Index worst = -1;
  Real amplitude = 0;
  for (Index i = 0; i < field.size(); ++i) {
    const Real value = std::abs(field[i]);
    if (!std::isfinite(value)) {
      worst = i;
      amplitude = value;
      break;
    }
    if (value > amplitude) {
      amplitude = value;
      worst = i;
    }
  }
  auto fail = [&](const std::string& why) {
    std::ostringstream message;
    message.precision(6);
    const long particle = static_cast<long>(worst / options_.components);
    const long component = static_cast<long>(worst % options_.components);
    message << "numerical instability at step " << state.step << ", t = " << state.time << ": " << why
            << " in " << name << " of particle " << particle << " (component " << component
            << ", value " << field[worst] << ")";
    throw InstabilityError(message.str(), state.step, state.time, particle);
  };
  if (worst >= 0 && !std::isfinite(amplitude)) fail("non-finite value");
  if (amplitude > options_.absoluteLimit) {
    std::ostringstream why;
    why << "amplitude " << amplitude << " above the limit " << options_.absoluteLimit;
    fail(why.str());
  }
  if (reference > 0 && amplitude > options_.growthFactor * reference) {
    std::ostringstream why;
    why << "runaway growth: amplitude " << amplitude << " is more than " << options_.growthFactor
        << " times its earlier maximum " << reference;
    fail(why.str());
  }
  // The reference is the largest amplitude seen at least `window` observations ago.
  history.push_back(amplitude);
  if (static_cast<long>(history.size()) > options_.window) {
    reference = std::max(reference, history.front());
    history.pop_front();
  }
}

}  // namespace mfwave
