#include "integrators/TimeStep.hpp"

#include "core/Error.hpp"
#include "core/NumberText.hpp"

#include <algorithm>
#include <cmath>

namespace mfwave {

TimeStepChoice chooseTimeStep(const TimeStepRule& rule, Real stableStep) {
  const bool fixed = rule.fixedStep.has_value();
  const Real step = fixed ? *rule.fixedStep : rule.cfl * stableStep;
  if (std::isnan(step) || !(step > 0))
    throw InputError(fixed ? "integrator.time_step" : "integrator.cfl",
                     "the step " + shortestNumber(step) + " s is not positive (stable step " +
                         shortestNumber(stableStep) + " s)");
  // A fixed step divides the end time (checked where it is read): round; a fraction of the stable
  // step is shortened to land on the end, never lengthened (1e-9: a step that divides up to
  // round-off is taken as it is). An unbounded stable step (no finite frequency) takes one step.
  const Real steps = fixed ? std::round(rule.endTime / step) : std::ceil(rule.endTime / step - 1e-9);
  const std::string problem =
      tooManySteps(steps, shortestNumber(rule.endTime) + " s at a step of " + shortestNumber(step) + " s");
  if (!problem.empty()) throw InputError(fixed ? "integrator.time_step" : "integrator.end_time", problem);
  TimeStepChoice choice;
  choice.steps = std::max(1L, static_cast<long>(steps));
  choice.dt = rule.endTime / static_cast<Real>(choice.steps);
  choice.stableStep = stableStep;
  return choice;
}

Real centralDifferenceStableStep(Real omegaMax) {
  if (!(omegaMax > 0) || !std::isfinite(omegaMax))
    throw InputError("omega_max", "must be positive and finite, got " + shortestNumber(omegaMax));
  return 2 / omegaMax;
}

std::string tooManySteps(Real steps, const std::string& what) {
  if (steps <= TimeStepRule::kMaxSteps) return "";
  return what + " is " + shortestNumber(steps) + " steps; more than " + shortestNumber(TimeStepRule::kMaxSteps) + " is refused";
}

}  // namespace mfwave
