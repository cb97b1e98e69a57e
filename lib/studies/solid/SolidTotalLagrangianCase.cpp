// The solid study's total-Lagrangian SPH case (runSolidTotalLagrangianCase, SolidStudy.hpp): the
// total-Lagrangian SPH for elastic solids (docs/theory/total-lagrangian-sph.md: reference pairs
// computed once, corrected kernel gradients, Saint Venant-Kirchhoff stress, the variational hourglass
// penalty, no artificial terms) on the same body-fitted fill as the UL-SPH case (SolidParticleFill),
// at the same small amplitude.
//
//   options     the method's defaults (cubic spline, h = 1.3 dx, hourglass factor 1) with the scene's
//               material
//   load        the surface forces of the UL-SPH case, eps times the scene's, as accelerations
//               force / (rho0 V) on their particles (ForcedSecondOrderSystem: the method has no load)
//   faces       the box's faces and the solid's surfaces free
//   integrator  the scene's (central difference) at integrator.cfl of 2 / omega_max, omega_max^2 by
//               the method's power iteration on its operator linearised about rest
//   probes      as the UL-SPH case's: linear RK interpolation over the particles, over eps

#include "studies/solid/SolidStudy.hpp"

#include "core/Stopwatch.hpp"
#include "integrators/IntegratorFactory.hpp"
#include "integrators/TimeStep.hpp"
#include "io/run/ProgressReporter.hpp"
#include "io/scene/Format.hpp"
#include "methods/total_lagrangian_sph/TotalLagrangianSph.hpp"
#include "observers/StabilityMonitor.hpp"
#include "observers/TimeLoop.hpp"
#include "studies/solid/SolidCase.hpp"
#include "studies/solid/SolidParticleFill.hpp"
#include "systems/ForcedSecondOrderSystem.hpp"

#include <cmath>

namespace mfwave::solid {

template <int D>
SolidCaseResult runSolidTotalLagrangianCase(const SolidPlan<D>& plan, Real spacing, const std::string& folder,
                                            bool progress) {
  const Scene& scene = plan.scene;
  const Stopwatch setup;
  SolidCaseResult result = startCase("tlsph", "total_lagrangian_sph", "fill", spacing);
  const Real eps = kSmallAmplitude;
  const FilledSolid<D> filled = fillSolid(plan, spacing, result);

  TotalLagrangianSphOptions options;
  options.material = plan.solid.materials[0];
  options.smoothingLengthRatio = filled.ratioFor(options.smoothingLengthRatio, spacing);
  options.interacts = crackFilter(plan, filled);  // the reference pairs across a crack left out
  TotalLagrangianSph<D> method(filled.particles, options);
  method.fixParticles(fixedParticles(plan, filled));  // [[surface_boundary]]: their surface particles clamped
  std::vector<SparseLoad> loads;
  const Real density = options.material.density();
  for (std::size_t l = 0; l < scene.loads.size(); ++l) {
    SparseLoad load;
    load.history = &scene.loads[l].timeFunction;
    for (const auto& [particle, force] : surfaceForces(plan, filled, l, spacing))
      for (int c = 0; c < D; ++c) {
        load.dofs.push_back(D * particle + c);
        load.values.push_back(eps * force[c] / (density * filled.fill.volume[static_cast<std::size_t>(particle)]));
      }
    loads.push_back(std::move(load));
  }
  ForcedSecondOrderSystem system(method, std::move(loads));

  result.stableStep = centralDifferenceStableStep(std::sqrt(method.largestFrequencySquared()));
  const TimeStepChoice step = chooseTimeStep(scene.integrator.stepRule(), result.stableStep);
  result.dt = step.dt;
  const std::unique_ptr<SecondOrderIntegrator> integrator =
      makeSecondOrderIntegrator(scene.integrator.name, scene.integrator.options);
  integrator->initialise(system, 0, Vector::Zero(system.size()), Vector::Zero(system.size()), step.dt);

  std::vector<bool> velocity;
  for (const SolidProbe<D>& p : plan.probes) velocity.push_back(p.velocity);
  SampledProbes probes(probeNames(plan), rowSampler(probeRows(plan, filled, spacing, 1 / eps), std::move(velocity)));
  StabilityMonitor monitor(scene.stability.options(D, loadsQuietAfter(scene)));
  ProgressReporter reporter(scene.integrator.endTime, filled.fill.size(), progress);
  TimeLoop loop;
  loop.add(monitor);
  loop.add(reporter);
  if (!plan.probes.empty()) loop.add(probes, scene.output.probeEvery);
  result.setupSeconds = setup.seconds();
  const RunStatistics stats = runCase(loop, *integrator, scene.integrator.endTime, plan, probes, folder, result,
                                      particleWhere(filled, "total-Lagrangian SPH", result.name));
  recordRun(result, stats);
  writeAndScoreProbes(plan, probes.series(), folder, result);
  return result;
}

template SolidCaseResult runSolidTotalLagrangianCase<2>(const SolidPlan<2>&, Real, const std::string&, bool);
template SolidCaseResult runSolidTotalLagrangianCase<3>(const SolidPlan<3>&, Real, const std::string&, bool);

}  // namespace mfwave::solid
