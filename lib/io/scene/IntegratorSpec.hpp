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
#include "integrators/TimeStep.hpp"
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

  // The step rule this section gives (integrators/TimeStep: the step's one home).
  TimeStepRule stepRule() const { return {endTime, timeStep, cfl}; }
  // chooseTimeStep(stepRule(), stableStep): timeStep, or the largest step <= cfl * stableStep that
  // divides endTime into whole steps; more than TimeStepRule::kMaxSteps steps are refused, naming
  // integrator.end_time (or time_step), exit 2.
  Real timeStepFor(Real stableStep) const { return chooseTimeStep(stepRule(), stableStep).dt; }
  long stepsFor(Real stableStep) const { return chooseTimeStep(stepRule(), stableStep).steps; }
};

IntegratorSpec readIntegrator(SceneReader& reader);

// For drivers of first-order systems: integrator.name takes firstOrderIntegratorNames() (default
// "leapfrog") and integrator.cfl defaults to 1. Call before loading the scene.
void useFirstOrderIntegrators(SceneSchema& schema);
// True after useFirstOrderIntegrators (integrator.name offers the first-order names).
bool usesFirstOrderIntegrators(const SceneSchema& schema);
// readIntegrator for a first-order driver: name (a first-order one), end time, fixed step or cfl,
// and the ARKODE options. Throws std::logic_error unless useFirstOrderIntegrators was called.
IntegratorSpec readFirstOrderIntegrator(SceneReader& reader);

}  // namespace mfwave
