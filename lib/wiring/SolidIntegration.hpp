#pragma once
// Wires an updated-Lagrangian SPH system to a first-order integrator: the integrator named by the
// scene, started from y0, with the step chosen before every step by the method's CFL, viscous and
// force criteria (UpdatedLagrangianSph::stableStep) unless the scene fixes it.

#include "integrators/ArkodeExplicit.hpp"
#include "integrators/FirstOrderIntegrator.hpp"
#include "io/scene/IntegratorSpec.hpp"
#include "methods/updated_lagrangian_sph/UpdatedLagrangianSph.hpp"

#include <memory>
#include <string>

namespace mfwave {

struct SolidIntegrationSettings {
  std::string integrator = "leapfrog";  // firstOrderIntegratorNames()
  ArkodeOptions arkode;                 // "arkode": its table (the step is set here, not adaptive)
  Real fixedStep = 0;                   // > 0: this step throughout; 0: cfl times the method's stable step
  Real cfl = 1;                         // factor on the method's step criteria (which carry their Courant number)
};

// From the scene's [integrator] (read by readFirstOrderIntegrator): name, ARKODE table, time_step or cfl.
SolidIntegrationSettings solidIntegrationSettings(const IntegratorSpec& spec);

// Evaluates F(0, y0) once (so the force criterion has accelerations), then builds and initialises
// the integrator. Throws InputError("integrator.time_step") when a fixed step exceeds twice the
// method's stable step at t = 0 (a run that would blow up at once), and InputError(endTimeKey) when
// `endTime` at the first step is more than IntegratorSpec::kMaxSteps steps (a typo, not a run).
template <int D>
std::unique_ptr<FirstOrderIntegrator> makeSolidIntegrator(UpdatedLagrangianSph<D>& system, const Vector& y0,
                                                          const SolidIntegrationSettings& settings, Real endTime,
                                                          const std::string& endTimeKey = "integrator.end_time");

}  // namespace mfwave
