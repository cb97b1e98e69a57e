#include "integrators/FirstOrderIntegrator.hpp"

#include "core/Error.hpp"

#include <cmath>
#include <sstream>
#include <string>

namespace mfwave {

Real FirstOrderIntegrator::nextStepSize(Real current) const {
  if (!stepSizeRule_) return current;
  const Real dt = stepSizeRule_(time(), solution());
  if (!(dt > 0) || !std::isfinite(dt)) {
    std::ostringstream message;
    message.precision(10);
    message << name() << ": the step-size rule returned " << dt << " at step " << stepCount() << ", t = " << time()
            << " (the next step must be positive and finite)";
    throw InstabilityError(message.str(), stepCount(), time(), -1);
  }
  return dt;
}

void checkInitialState(const FirstOrderSystem& system, Real t0, const Vector& y0, Real dt) {
  const Index n = system.size();
  if (y0.size() != n || n == 0)
    throw InputError("initial_state", "y0 must have the system's size " + std::to_string(n) + " (> 0), got " +
                                          std::to_string(y0.size()));
  if (!y0.allFinite()) throw InputError("initial_state", "y0 must be finite");
  if (!std::isfinite(t0)) throw InputError("start_time", "must be finite");
  if (!(dt > 0) || !std::isfinite(dt))
    throw InputError("time_step", "must be positive and finite (got " + std::to_string(dt) + ")");
}

}  // namespace mfwave
