#include "integrators/Integrator.hpp"

#include "core/Error.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace mfwave {

void Integrator::advanceTo(Real t) {
  const Real dt = stepSize();
  if (!(dt > 0)) throw InputError("time_step", "must be positive before advancing");
  const Real remaining = t - time();
  if (remaining < -1e-12 * std::max(Real(1), std::abs(t)))
    throw InputError("end_time", "lies before the current time " + std::to_string(time()));
  const Real stepsExact = remaining / dt;
  const long steps = std::lround(stepsExact);
  if (std::abs(stepsExact - static_cast<Real>(steps)) > 1e-8 * std::max(Real(1), stepsExact))
    throw InputError("end_time", "is not a whole number of steps of size " + std::to_string(dt) +
                                     " from t = " + std::to_string(time()));
  for (long i = 0; i < steps; ++i) step();
}

void Integrator::saveState(StateArchive&) const {
  throw Error("the integrator " + name() + " cannot be checkpointed yet");
}

void Integrator::restoreState(const StateArchive&) {
  throw Error("the integrator " + name() + " cannot be checkpointed yet");
}

void checkInitialState(const SecondOrderSystem& system, Real t0, const Vector& u0, const Vector& v0, Real dt) {
  const Index n = system.size();
  if (u0.size() != n || v0.size() != n)
    throw InputError("initial_state", "u0 and v0 must both have the system's size " + std::to_string(n) +
                                          " (got " + std::to_string(u0.size()) + " and " +
                                          std::to_string(v0.size()) + ")");
  if (!u0.allFinite() || !v0.allFinite()) throw InputError("initial_state", "u0 and v0 must be finite");
  if (!std::isfinite(t0)) throw InputError("start_time", "must be finite");
  if (!(dt > 0) || !std::isfinite(dt))
    throw InputError("time_step", "must be positive and finite (got " + std::to_string(dt) + ")");
}

}  // namespace mfwave
