// The solid study's RK collocation case (runSolidCollocationCase, SolidStudy.hpp): Luo-Liu-Huang's
// strong-form collocation with reproducing-kernel shape functions on the nodes of a solid the scene
// describes (methods/collocation/SolidCollocationNodes).
//
//   interior rows      lattice nodes at least half a spacing inside the solid: rho u'' - L u = 0
//   traction rows      points on the solid's own surfaces: sigma(u) n = h(x, t) with n the surface's
//                      outward normal there (eq. (13)); free box faces likewise with the face's normal
//   displacement rows  the box's other nodes in the solid: u = 0 (transmitting faces run fixed, as
//                      in the Lamb studies; the catalogue's stand-in, noted in the summary)
//
// A surface_traction load gives h = (-p n or the vector) w(x) f(t) at the surface nodes of its named
// surface, w the share of the node's tributary length s (SolidCollocationNodes::surfaceSpacing)
// within the load's radius, clamp((r - |x - c|) / s + 1/2, 0, 1): on a line of nodes s apart it is
// the trapezoid rule's 1, 1/2 at an edge on a node, 0 outside, and the total force is the load's to
// O(s^2) wherever the edges fall. The step is integrator.cfl of 2 / omega_max (power iteration on the
// constrained operator); probes read u^h (or its rate) along their directions at any point, without
// a solve (CollocationSampler).

#include "studies/solid/SolidStudy.hpp"

#include "core/Error.hpp"
#include "core/Stopwatch.hpp"
#include "integrators/ConstrainedIntegrators.hpp"
#include "integrators/TimeStep.hpp"
#include "io/run/ProgressReporter.hpp"
#include "io/run/RunSummary.hpp"
#include "io/scene/Format.hpp"
#include "io/vtk/FrameOutputs.hpp"
#include "methods/collocation/CollocationSampler.hpp"
#include "methods/collocation/ConstrainedCollocationSystem.hpp"
#include "methods/collocation/SolidCollocationNodes.hpp"
#include "numerics/StableTimeStep.hpp"
#include "observers/StabilityMonitor.hpp"
#include "observers/TimeLoop.hpp"
#include "particles/BoxFace.hpp"
#include "studies/solid/SolidCase.hpp"
#include "systems/SparseLoads.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace mfwave::solid {

template <int D>
SolidCaseResult runSolidCollocationCase(const SolidPlan<D>& plan, Real spacing, const std::string& folder, bool frames,
                                        bool progress) {
  const Scene& scene = plan.scene;
  const Stopwatch setup;
  SolidCaseResult result = startCase("rk", "reproducing_kernel", "nodes", spacing);

  // nodes: the solid's own surfaces carry traction rows, the box's faces are the lattice's
  const SceneSolid<D>& solid = plan.solid;
  CollocationSolid<D> domain;
  domain.distance = [surfaces = solid.unbounded](const Vec<D>& x) { return surfaces->signedDistance(x); };
  domain.normal = [surfaces = solid.unbounded](const Vec<D>& x) { return surfaces->normal(x); };
  domain.lower = scene::vectorOf<D>(scene.geometry.lower);
  domain.upper = scene::vectorOf<D>(scene.geometry.upper);
  domain.freeFaces = facesWith(scene.boundaries, BoundaryType::Free);
  if (!plan.fixedSurfaces.empty()) domain.clamped = [&plan](const Vec<D>& x) { return plan.fixedAt(x); };
  const SolidCollocationNodes<D> nodes = solidCollocationNodes<D>(domain, spacing);
  result.unknowns = nodes.size();
  result.cutCells = nodes.surface;  // the surface nodes stand where the cut cells do
  const std::unique_ptr<ShapeFunctions<D>> shapes = makeCollocationShapes<D>(plan.collocation, nodes.nodes, spacing);

  // the loads at the surface nodes: one vector over the rows per load, scaled by its history
  const Index rows = D * nodes.size();
  std::vector<SparseLoad> loads;
  for (std::size_t l = 0; l < scene.loads.size(); ++l) {
    const LoadSpec& load = scene.loads[l];  // surface_traction: the catalogue refuses the others
    const Vec<D> centre = scene::vectorOf<D>(load.centre);
    const bool pressure = load.traction.empty();
    const Vec<D> vector = pressure ? Vec<D>::Zero() : scene::vectorOf<D>(load.traction);
    Vector b = Vector::Zero(rows);
    for (Index i = 0; i < nodes.size(); ++i) {
      if (!nodes.onSurface(i) || nodes.points.kind[static_cast<std::size_t>(i)] != CollocationRowKind::Traction) continue;
      const Vec<D> x = nodes.position(i);
      if (solid.solid->surfaceName(x) != load.surface) continue;
      const Real s = nodes.surfaceSpacing[static_cast<std::size_t>(i)];
      const Real w = surfaceLoadShare(load.radius, (x - centre).norm(), s);
      if (w == 0) continue;
      const Vec<D> n = nodes.points.normal[static_cast<std::size_t>(i)];
      b.template segment<D>(D * i) = w * (pressure ? Vec<D>(-load.pressure * n) : vector);
    }
    if (!(b.cwiseAbs().maxCoeff() > 0))
      throw InputError("load[" + std::to_string(l) + "].surface",
                       "no surface node of '" + load.surface + "' lies within " + scene::formatNumber(load.radius) +
                           " of " + scene::formatPoint(load.centre) + " at spacing " + scene::formatNumber(spacing));
    loads.push_back(nonzeroLoad(b, &load.timeFunction));
  }
  CollocationSystem assembled = assembleCollocation<D>(*shapes, nodes.points, solid.materials[0]);
  if (!loads.empty())
    assembled.load = [loads, rows](Real t, Vector& b) {
      b.setZero(rows);
      addSparseLoads(loads, t, b.data());
    };
  ConstrainedCollocationSystem system(std::move(assembled));

  // the step: cfl of 2 / omega_max (power iteration on the constrained operator), or the scene's fixed step
  const AccelerationSpectralRadius radius = accelerationSpectralRadius(system);
  result.stableStep = centralDifferenceStableStep(std::sqrt(radius.value));
  const TimeStepChoice step = chooseTimeStep(scene.integrator.stepRule(), result.stableStep);
  result.dt = step.dt;
  const std::unique_ptr<SecondOrderIntegrator> integrator =
      makeConstrainedIntegrator(scene.integrator.name, scene.integrator.options);
  integrator->initialise(system, 0, Vector::Zero(system.size()), Vector::Zero(system.size()), step.dt);

  // probes: u^h (or its rate) along each direction at its position
  Eigen::MatrixXd functionals = Eigen::MatrixXd::Zero(system.system().cols(), static_cast<Index>(plan.probes.size()));
  const std::vector<std::vector<std::pair<Index, Real>>> probeRows = shapeFunctionRows(*shapes, plan.probes, 1.0);
  std::vector<bool> rate;
  for (std::size_t p = 0; p < plan.probes.size(); ++p) {
    for (const auto& [dof, w] : probeRows[p]) functionals(dof, static_cast<Index>(p)) += w;
    rate.push_back(plan.probes[p].velocity);
  }
  const CollocationSampler sampler(system, functionals);
  SampledProbes probes(probeNames(plan), [&sampler, rate](const StateView& state) {
    return sampler.sample(state.time, state.displacement, state.velocity, rate);
  });

  StabilityMonitor monitor(scene.stability.options(D, loadsQuietAfter(scene)));
  ProgressReporter reporter(scene.integrator.endTime, nodes.size(), progress);
  TimeLoop loop;
  loop.add(monitor);
  loop.add(reporter);
  if (!plan.probes.empty()) loop.add(probes, scene.output.probeEvery);
  // frames of the interior nodes, whose values are the state itself (U = Psi_I d)
  ParticleSet<D> interior;
  for (Index a = 0; a < nodes.interior; ++a) interior.add(nodes.position(a), solid.materials[0].density() * std::pow(spacing, D));
  ParticleFrames<D> particleFrames(interior, folder, result.name, frameSettings<D>(scene.output, frames));
  particleFrames.attachTo(loop, scene.output.every);
  result.setupSeconds = setup.seconds();
  const RunStatistics stats = runCase(loop, *integrator, scene.integrator.endTime, plan, probes, folder, result,
                                      [&](long particle) -> std::string {
    // the monitor's particle is the interior unknown's point: said as the node it is
    if (D * particle >= system.size()) return "";
    const Index node = system.interiorRows()[static_cast<std::size_t>(D * particle)] / D;
    const Vec<D> x = nodes.position(node);
    return "RK collocation on the solid, case " + result.name + ": node " + std::to_string(node) + " at " +
           scene::formatPoint(std::vector<Real>(x.data(), x.data() + D));
  });
  recordRun(result, stats);
  writeAndScoreProbes(plan, probes.series(), folder, result);
  return result;
}

template SolidCaseResult runSolidCollocationCase<2>(const SolidPlan<2>&, Real, const std::string&, bool, bool);
template SolidCaseResult runSolidCollocationCase<3>(const SolidPlan<3>&, Real, const std::string&, bool, bool);

}  // namespace mfwave::solid
