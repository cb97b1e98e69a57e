#include "io/scene/StepLimitCheck.hpp"

#include "core/Error.hpp"
#include "integrators/StabilityLimit.hpp"

#include <cmath>
#include <sstream>

namespace mfwave {

StepLimitCheck checkStepLimit(const IntegratorSpec& integrator, const StabilitySpec& stability, Real omegaMax,
                              Real dt, Real cflStep, const std::string& omegaSource, const std::string& context) {
  const StepVerdict verdict = judgeStep(integrator.name, integrator.options, omegaMax, dt);
  StepLimitCheck out;
  out.limitDt = verdict.limitDt;
  if (!verdict.aboveLimit) return out;
  std::ostringstream what;
  what.precision(6);
  std::string key, advice;
  if (verdict.integratorUnstable) {
    const bool newmark = integrator.kind == IntegratorKind::Newmark;
    key = newmark ? "integrator.newmark_gamma" : "integrator.arkode_table";
    what << verdict.limit.integrator << " lets undamped modes grow at any step (" << verdict.limit.note
         << "); " << context << " the fastest mode (omega_max = " << omegaMax << ", from " << omegaSource
         << ") grows by a factor " << verdict.growthPerStep << " per step";
    advice = newmark ? "use newmark_gamma >= 0.5" : "use a table with an imaginary-axis limit (classic_rk4, "
                                                    "zonneveld_5_3_4, ark436_explicit: see the stability atlas)";
  } else {
    key = integrator.timeStep ? "integrator.time_step" : "integrator.cfl";
    what << "the step " << dt << " exceeds the " << verdict.limit.integrator << " limit " << verdict.limit.omegaDtLimit
         << " / omega_max = " << verdict.limitDt << " " << context << " (" << dt / verdict.limitDt
         << " x; omega_max = " << omegaMax << " from " << omegaSource << "): the fastest mode grows by a factor "
         << verdict.growthPerStep << " per step";
    std::ostringstream give;
    give.precision(6);
    if (integrator.timeStep)
      give << "give a time_step <= " << verdict.limitDt;
    else
      give << "use cfl <= " << verdict.limitDt / cflStep;
    advice = give.str();
  }
  if (!stability.allowGrowth)
    throw InputError(key, what.str() + "; " + advice + ", or stability.allow_growth = true to run there on purpose");
  out.note = "stability.allow_growth: ran although " + what.str();
  return out;
}

std::string refuseGrowingModes(const StabilitySpec& stability, const std::string& what, const std::string& advice) {
  if (!stability.allowGrowth)
    throw InstabilityError(what + ", so the run is refused before stepping (" + advice +
                               "; stability.allow_growth = true runs it on purpose)",
                           0, 0.0, -1);
  return "stability.allow_growth: ran although " + what;
}

}  // namespace mfwave
