#pragma once
// [integrator]: which second-order integrator, until when, and with which step: a fixed
// time_step, or cfl times the method's stable step (cfl = 0.5 when neither is given).

#include "integrators/IntegratorFactory.hpp"
#include "io/scene/SceneReader.hpp"

#include <optional>
#include <string>

namespace mfwave {

struct IntegratorSpec {
  std::string name = "central_difference";  // one of secondOrderIntegratorNames()
  Real endTime = 0;
  std::optional<Real> timeStep;  // given: the step (it divides endTime)
  Real cfl = 0.5;                // used when timeStep is not given
  IntegratorOptions options;     // newmark beta/gamma, ARKODE table/adaptive/tolerances

  // The step to run with: timeStep, or the largest step <= cfl * stableStep that divides
  // endTime into whole steps.
  Real timeStepFor(Real stableStep) const;
  long stepsFor(Real stableStep) const;  // endTime / timeStepFor(stableStep), rounded
};

IntegratorSpec readIntegrator(SceneReader& reader);

}  // namespace mfwave
