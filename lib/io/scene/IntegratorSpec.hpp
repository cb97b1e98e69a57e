#pragma once
// [integrator]: which integrator, until when, and with which step: a fixed time_step, or cfl times
// the method's stable step (cfl = 0.5 when neither is given).
//
// Most drivers run second-order systems (secondOrderIntegratorNames()). A driver of a first-order
// system (the updated-Lagrangian SPH) calls useFirstOrderIntegrators(schema) before loading the
// scene: integrator.name then takes firstOrderIntegratorNames() (default "leapfrog") and cfl
// defaults to 1, a factor on the method's own step criteria (which carry their own Courant number).
// readScene reads either kind; readFirstOrderIntegrator says that the schema is first-order.

#include "integrators/IntegratorFactory.hpp"
#include "integrators/IntegratorKind.hpp"
#include "io/scene/SceneReader.hpp"
#include "io/scene/SceneSchema.hpp"

#include <optional>
#include <string>

namespace mfwave {

struct IntegratorSpec {
  std::string name = "central_difference";  // secondOrderIntegratorNames(), or firstOrderIntegratorNames()
  IntegratorKind kind = IntegratorKind::CentralDifference;  // what `name` stands for
  Real endTime = 0;
  std::optional<Real> timeStep;  // given: the step (it divides endTime)
  Real cfl = 0.5;                // used when timeStep is not given (1 by default for first-order)
  IntegratorOptions options;     // newmark beta/gamma, ARKODE table/adaptive/tolerances (options.arkode)

  // The most steps a run may take (1e12: days at 10^7 steps/s); stepsFor refuses more, naming
  // integrator.end_time (or time_step), exit 2.
  static constexpr Real kMaxSteps = 1e12;
  // The step to run with: timeStep, or the largest step <= cfl * stableStep that divides
  // endTime into whole steps.
  Real timeStepFor(Real stableStep) const;
  long stepsFor(Real stableStep) const;  // endTime / timeStepFor(stableStep), rounded
};

IntegratorSpec readIntegrator(SceneReader& reader);

// The one check of a run's length: empty when `steps` is at most IntegratorSpec::kMaxSteps, else the
// problem to report against the caller's key, "<what> is <steps> steps; more than 1e12 is refused"
// (a typo such as end_time = 1e300, not a run; it would overflow the step counter).
std::string tooManySteps(Real steps, const std::string& what);

// For drivers of first-order systems: integrator.name takes firstOrderIntegratorNames() (default
// "leapfrog") and integrator.cfl defaults to 1. Call before loading the scene.
void useFirstOrderIntegrators(SceneSchema& schema);
// True after useFirstOrderIntegrators (integrator.name offers the first-order names).
bool usesFirstOrderIntegrators(const SceneSchema& schema);
// readIntegrator for a first-order driver: name (a first-order one), end time, fixed step or cfl,
// and the ARKODE options. Throws std::logic_error unless useFirstOrderIntegrators was called.
IntegratorSpec readFirstOrderIntegrator(SceneReader& reader);

}  // namespace mfwave
