#include "integrators/Integrator.hpp"

#include "core/Error.hpp"

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

}  // namespace mfwave
