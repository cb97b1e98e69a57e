#include "wiring/SolidIntegration.hpp"

#include "core/Error.hpp"
#include "integrators/FirstOrderIntegratorFactory.hpp"

#include <cmath>
#include <sstream>

namespace mfwave {

SolidIntegrationSettings solidIntegrationSettings(const IntegratorSpec& spec) {
  SolidIntegrationSettings settings;
  settings.integrator = spec.name;
  settings.arkode = spec.options.arkode;
  settings.fixedStep = spec.timeStep.value_or(0);
  // With a fixed time_step the scene has no cfl (IntegratorSpec leaves it unset): the method's own
  // criteria (cfl 1) are then the reference the step is checked against.
  settings.cfl = spec.timeStep ? 1.0 : spec.cfl;
  return settings;
}

template <int D>
std::unique_ptr<FirstOrderIntegrator> makeSolidIntegrator(UpdatedLagrangianSph<D>& system, const Vector& y0,
                                                          const SolidIntegrationSettings& settings, Real endTime,
                                                          const std::string& endTimeKey) {
  if (!(settings.cfl > 0) || !std::isfinite(settings.cfl)) throw InputError("integrator.cfl", "must be positive");
  const Real stable = settings.cfl * system.evaluateStepCriteria(0, y0);
  if (settings.fixedStep > 2 * stable) {
    std::ostringstream why;
    why << "is " << settings.fixedStep << ", more than twice the stable step " << stable
        << " of the CFL, viscous and force criteria at t = 0";
    throw InputError("integrator.time_step", why.str());
  }
  const Real firstStep = settings.fixedStep > 0 ? settings.fixedStep : stable;
  std::ostringstream what;
  what << endTime << " s at the first step of " << firstStep << " s";
  const std::string tooMany = tooManySteps(endTime / firstStep, what.str());
  if (!tooMany.empty()) throw InputError(endTimeKey, tooMany);
  std::unique_ptr<FirstOrderIntegrator> integrator = makeFirstOrderIntegrator(settings.integrator, settings.arkode);
  if (settings.fixedStep > 0) {
    integrator->initialise(system, 0, y0, settings.fixedStep);
  } else {
    integrator->initialise(system, 0, y0, stable);
    const Real cfl = settings.cfl;
    integrator->setStepSizeFunction([&system, cfl](Real, const Vector& y) { return cfl * system.stableStep(y); });
  }
  return integrator;
}

template std::unique_ptr<FirstOrderIntegrator> makeSolidIntegrator<1>(UpdatedLagrangianSph<1>&, const Vector&,
                                                                      const SolidIntegrationSettings&, Real,
                                                                      const std::string&);
template std::unique_ptr<FirstOrderIntegrator> makeSolidIntegrator<2>(UpdatedLagrangianSph<2>&, const Vector&,
                                                                      const SolidIntegrationSettings&, Real,
                                                                      const std::string&);
template std::unique_ptr<FirstOrderIntegrator> makeSolidIntegrator<3>(UpdatedLagrangianSph<3>&, const Vector&,
                                                                      const SolidIntegrationSettings&, Real,
                                                                      const std::string&);

}  // namespace mfwave
