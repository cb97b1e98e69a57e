// The solid study's updated-Lagrangian SPH case (runSolidSphCase, SolidStudy.hpp): the SPH for solids
// of Li's primer on a body-fitted fill of the scene's solid (geometry/ParticleFill), at small
// amplitude so that the large-deformation method answers the linear problem, as in the Lamb study
// (studies/lamb3d/LambSolidCase.hpp: its choices and why).
//
//   particles   one per lattice cell that meets the solid, at the centroid of the cell's inside part
//               where the surface cuts it, with that part's volume (m = rho0 V; the volumes add up
//               to the solid's; slivers below 0.1 of a cell merged into a neighbour)
//   options     smallAmplitudeWaveOptions: cubic spline, h = 1.3 dx, continuity density, gamma = 1
//               EOS, Jaumann rate, artificial viscosity alpha = 1, the kernel-gradient correction on
//               (which makes a surface particle's cut support first-order consistent)
//   load        a surface_traction load's pressure (along the particle's inward normal) or vector,
//               eps times the scene's, on the surface particles of its named surface: each carries
//               its share of the surface (ParticleFill's area) times w = clamp((r - |p - c|) / s +
//               1/2, 0, 1), p the particle projected onto the surface, s its surface spacing (the
//               area in 2-D, its square root in 3-D); the probes record v / eps
//   cracks      pairs whose segment (between the particles' initial positions) crosses a [[crack]]
//               are cut from the neighbour lists at every rebuild (the visibility criterion)
//   faces       the box's faces free (the method has no dashpot: transmitting faces run free, the
//               catalogue's stand-in); the solid's own surfaces are free
//   integrator  leapfrog at the method's own step criteria, every step (the scene's integrator.name
//               and cfl are not used: the summary says so)
//   probes      u^h or v^h along each direction at any point: linear reproducing-kernel (moving
//               least squares, m = 1) interpolation over the particles' initial positions (support
//               2.5 dx), exact for a linear field, so a probe on the surface is not biased by the
//               particles' lying on one side of it.

#include "studies/solid/SolidStudy.hpp"

#include "core/Error.hpp"
#include "core/Stopwatch.hpp"
#include "io/run/ProgressReporter.hpp"
#include "io/run/RunSummary.hpp"
#include "io/scene/Format.hpp"
#include "methods/updated_lagrangian_sph/UpdatedLagrangianSph.hpp"
#include "observers/StabilityMonitor.hpp"
#include "observers/TimeLoop.hpp"
#include "studies/solid/SolidCase.hpp"
#include "studies/solid/SolidParticleFill.hpp"
#include "wiring/SolidIntegration.hpp"
#include "wiring/SolidStateAdapter.hpp"
#include "wiring/UpdatedLagrangianSphSpec.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace mfwave::solid {

template <int D>
SolidCaseResult runSolidSphCase(const SolidPlan<D>& plan, Real spacing, const std::string& folder, bool progress) {
  const Scene& scene = plan.scene;
  const Stopwatch setup;
  SolidCaseResult result = startCase("ulsph", "updated_lagrangian_sph", "fill", spacing);
  const Real eps = kSmallAmplitude;

  const SceneSolid<D>& solid = plan.solid;
  const FilledSolid<D> filled = fillSolid(plan, spacing, result);

  UpdatedLagrangianSphOptions options = smallAmplitudeWaveOptions(solid.materials[0]);
  options.smoothingLengthRatio = filled.ratioFor(options.smoothingLengthRatio, spacing);
  options.interacts = crackFilter(plan, filled);  // the visibility criterion on the initial positions
  UpdatedLagrangianSph<D> system(filled.particles, options);
  system.fixParticles(fixedParticles(plan, filled));  // [[surface_boundary]]: their surface particles clamped
  for (std::size_t l = 0; l < scene.loads.size(); ++l)
    for (const auto& [particle, force] : surfaceForces(plan, filled, l, spacing))
      system.addTraction({particle}, eps * force, scene.loads[l].timeFunction, 1.0);
  const Vector y0 = system.initialState();
  SolidIntegrationSettings integration;
  integration.integrator = "leapfrog";
  integration.cfl = 1;  // the method's criteria carry their Courant number
  const std::unique_ptr<FirstOrderIntegrator> integrator =
      makeSolidIntegrator(system, y0, integration, scene.integrator.endTime);
  result.stableStep = system.stableStep(y0);
  result.dt = result.stableStep;

  // probes: linear RK interpolation over the initial positions, along each direction, over eps
  std::vector<bool> velocity;
  for (const SolidProbe<D>& p : plan.probes) velocity.push_back(p.velocity);
  SampledProbes probes(probeNames(plan), rowSampler(probeRows(plan, filled, spacing, 1 / eps), std::move(velocity)));

  SolidStateAdapter<D> adapter(system, filled.particles);
  StabilityMonitor monitor(scene.stability.options(D, loadsQuietAfter(scene)));
  adapter.add(monitor, 1);
  if (!plan.probes.empty()) adapter.add(probes, scene.output.probeEvery);
  ProgressReporter reporter(scene.integrator.endTime, filled.fill.size(), progress);
  TimeLoop loop;
  loop.add(reporter);
  loop.add(adapter);
  result.setupSeconds = setup.seconds();
  const RunStatistics stats = runCase(loop, *integrator, scene.integrator.endTime, plan, probes, folder, result,
                                      particleWhere(filled, "updated-Lagrangian SPH", result.name));
  recordRun(result, stats);
  if (stats.steps > 0) result.dt = (stats.endTime - stats.startTime) / static_cast<Real>(stats.steps);
  writeAndScoreProbes(plan, probes.series(), folder, result);
  return result;
}

template SolidCaseResult runSolidSphCase<2>(const SolidPlan<2>&, Real, const std::string&, bool);
template SolidCaseResult runSolidSphCase<3>(const SolidPlan<3>&, Real, const std::string&, bool);

}  // namespace mfwave::solid
