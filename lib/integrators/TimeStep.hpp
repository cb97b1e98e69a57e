#pragma once
// The time step's one home: every driver, study and tool turns the scene's [integrator] and the
// system's stable step into the step it runs with here, and nowhere else.
//
// A run either gives a fixed step (integrator.time_step, which must divide the end time) or a
// fraction cfl of the system's stable step: the step cfl multiplies, 2 / omega_max for a linear
// operator (central difference's limit; omega_max from the exact spectrum, a Gershgorin bound or a
// power iteration) or the method's own step criteria for the updated-Lagrangian SPH. The step is
// then shortened to the largest one <= cfl * stableStep that lands on the end time in whole steps,
// so every run ends exactly at end_time. The integrator's own limit L / omega_max
// (StabilityLimit.hpp) is judged on the chosen step (judgeStep); whether a step beyond it is an
// error or a note is the caller's (io/scene/StepLimitCheck), not this file's.

#include "core/Types.hpp"

#include <optional>
#include <string>

namespace mfwave {

struct TimeStepRule {
  Real endTime = 0;
  std::optional<Real> fixedStep;  // integrator.time_step when given
  Real cfl = 0.5;                 // fraction of the stable step when fixedStep is not given

  // The most steps a run may take (1e12: days at 10^7 steps/s); more is refused, naming
  // integrator.end_time (or time_step), exit 2: a typo such as end_time = 1e300, not a run.
  static constexpr Real kMaxSteps = 1e12;
};

struct TimeStepChoice {
  Real dt = 0;          // endTime / steps
  long steps = 0;       // at least 1
  Real stableStep = 0;  // the step cfl multiplied (unused with a fixed step)
};

// The step and step count of `rule` on a system whose stable step is `stableStep` (> 0, infinity
// for one step; ignored with a fixed step). Throws InputError("integrator.time_step" or
// "integrator.end_time") for more than kMaxSteps steps, InputError("integrator.cfl") for a step
// that is not positive.
TimeStepChoice chooseTimeStep(const TimeStepRule& rule, Real stableStep);

// The central-difference limit 2 / omega_max: the stable step integrator.cfl multiplies for a
// linear operator whose largest frequency is omegaMax (> 0, finite; else InputError("omega_max")).
Real centralDifferenceStableStep(Real omegaMax);

// Empty when `steps` is at most kMaxSteps, else the problem to report against the caller's key,
// "<what> is <steps> steps; more than 1e12 is refused".
std::string tooManySteps(Real steps, const std::string& what);

}  // namespace mfwave
