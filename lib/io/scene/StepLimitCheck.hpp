#pragma once
// Before stepping: is the run's fixed step stable for the operator the driver assembled?
//
// A driver knows the largest frequency omega_max of its operator (the exact spectrum on a lattice
// or a small system, a power iteration's bound on a large one); the integrator's limit L on one
// oscillator (integrators/StabilityLimit) makes the stable step L / omega_max for every integrator
// the scene can name. A step above it grows at every resolution, so the run is refused before any
// work with an InputError (exit 2) naming the key to change: integrator.time_step or
// integrator.cfl, or integrator.newmark_gamma / integrator.arkode_table when the integrator lets
// undamped modes grow at any step. stability.allow_growth = true runs there on purpose (to show a
// blow-up, which the monitors then stop with exit 3); the returned note says so in the summary.

#include "io/scene/IntegratorSpec.hpp"
#include "io/scene/StabilitySpec.hpp"

#include <string>

namespace mfwave {

struct StepLimitCheck {
  Real limitDt = 0;       // the stable step L / omega_max (infinity when unconditional)
  std::string note;       // "" within the limit; the summary's note when allow_growth ran above it
};

// `cflStep` is the step integrator.cfl multiplies (timeStepFor's argument), `omegaSource` says where
// omega_max comes from ("the exact spectrum of the operator"), `context` which case ("at 64
// cells"). Adaptive ARKODE runs have no fixed-step limit and pass.
StepLimitCheck checkStepLimit(const IntegratorSpec& integrator, const StabilitySpec& stability, Real omegaMax,
                              Real dt, Real cflStep, const std::string& omegaSource, const std::string& context);

// An operator with growing modes (`what` says which and where, e.g. "the RK collocation operator
// (...) has growing modes: ..."): no step is stable. Throws InstabilityError (exit 3) with `advice`
// (what to change), unless stability.allow_growth, and then returns the summary's note.
std::string refuseGrowingModes(const StabilitySpec& stability, const std::string& what, const std::string& advice);

}  // namespace mfwave
