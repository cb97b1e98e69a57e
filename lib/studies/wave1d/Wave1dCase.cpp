#include "Wave1dCase.hpp"

#include "numerics/StableTimeStep.hpp"
#include "analytic/StandingWave.hpp"
#include "core/Stopwatch.hpp"
#include "integrators/IntegratorFactory.hpp"
#include "io/scene/StepLimitCheck.hpp"
#include "methods/finite_difference/FiniteDifferenceWaveOperator.hpp"
#include "neighbours/NeighbourList.hpp"
#include "observers/EnergyObserver.hpp"
#include "observers/ProbeRecorder.hpp"
#include "observers/StabilityMonitor.hpp"
#include "observers/TimeLoop.hpp"
#include "particles/Lattice.hpp"

namespace mfwave::wave1d {

CaseResult runCase(const Study& study, const std::string& integratorName, int cellCount, const std::string& folder,
                   bool writeSeries) {
  const Stopwatch setup;
  const Scene& scene = study.scene;
  const Real x0 = scene.geometry.lower[0], length = scene.geometry.upper[0] - x0;
  const Real dx = length / cellCount;
  const Material& material = scene.material.material();
  const StandingWave exact(study.mode, length, material.pWaveSpeed(), 1, x0);

  // particles + neighbours
  const ParticleSet<1> line = makeLine(x0, x0 + length, dx);
  const NeighbourList neighbours = buildNeighbourList(CellList<1>(line, 1.5 * dx));
  // discretisation
  FiniteDifferenceWaveOptions fd;
  fd.spacing = dx;
  fd.density = material.density();
  fd.modulus = material.pWaveModulus();
  fd.fixedFaces = facesWith(scene.boundaries, BoundaryType::Fixed);
  LinearSecondOrderSystem system = assembleFiniteDifferenceWave(line, neighbours, fd);

  Vector u0(line.size()), v0(line.size());
  for (Index i = 0; i < line.size(); ++i) {
    u0[i] = exact.displacement(line.position(i)[0], 0);
    v0[i] = exact.velocity(line.position(i)[0], 0);
  }
  // integrator: the step is integrator.cfl times the stable central-difference step (the
  // Gershgorin bound, exact for this operator: dx / c), shortened to land on the end time.
  const Real criticalDt = centralDifferenceSafeStep(system);
  const Real dt = scene.integrator.timeStepFor(criticalDt);
  IntegratorOptions options = scene.integrator.options;
  auto integrator = makeSecondOrderIntegrator(integratorName, options);
  integrator->initialise(system, 0, u0, v0, dt);

  // observers
  StabilityMonitor monitor(scene.stability.options(1, 0));
  EnergyObserver energy(EnergyObserver::ofLinearSystem(system));
  const Index quarter = line.size() / 4;
  ProbeRecorder probes({{"quarter", quarter, 0, ProbeQuantity::Displacement}}, 1);
  TimeLoop loop;
  loop.add(monitor);
  loop.add(energy);
  if (writeSeries) loop.add(probes);
  const double setupSeconds = setup.seconds();
  const RunStatistics stats = loop.run(*integrator, scene.integrator.endTime);

  // error at the end time, relative to the L2 norm of the mode shape (u(T) itself may be small)
  const Vector& u = integrator->state().displacement;
  Real errorSquared = 0, normSquared = 0;
  for (Index i = 0; i < line.size(); ++i) {
    const Real x = line.position(i)[0];
    errorSquared += std::pow(u[i] - exact.displacement(x, stats.endTime), 2);
    normSquared += std::pow(std::sin(exact.wavenumber() * (x - x0)), 2);
  }
  CaseResult result;
  result.integrator = integratorName;
  result.cells = cellCount;
  result.dx = dx;
  result.error = std::sqrt(errorSquared / normSquared);
  result.energyDrift = energy.maxRelativeDrift();
  CaseRecord& record = result.record;
  record.name = integratorName + ", " + std::to_string(cellCount) + " cells";
  record.particles = cellCount + 1;
  result.recordLoop(stats);
  noteAllowedGrowth(result.notes, record.name, {monitor.growthMessage()});
  record.timeStep = dt;
  record.stableTimeStep = criticalDt;
  record.simulatedTime = scene.integrator.endTime;
  record.setupSeconds = setupSeconds;
  record.errors = {{"relative_l2", result.error}};
  record.primaryError = "relative_l2";
  if (writeSeries) {
    const std::string stem = integratorName + "-" + std::to_string(cellCount);
    probes.series().writeCsv(folder + "/" + stem + "-probe.csv");
    energy.series().writeCsv(folder + "/" + stem + "-energy.csv");
    result.files = {stem + "-probe.csv", stem + "-energy.csv"};
  }
  return result;
}

void refuseStepsAboveTheLimit(Study& study) {
  const Scene& scene = study.scene;
  const Real length = scene.geometry.upper[0] - scene.geometry.lower[0];
  const Real c = scene.material.material().pWaveSpeed();
  for (const auto& name : study.integrators) {
    IntegratorSpec integrator = scene.integrator;
    integrator.name = name;
    for (const int cells : study.cells) {
      const Real dx = length / cells;
      const Real dt = scene.integrator.timeStepFor(dx / c);
      const StepLimitCheck check = checkStepLimit(integrator, scene.stability, 2 * c / dx, dt, dx / c,
                                                  "the Gershgorin bound 2 c / dx", "at " + std::to_string(cells) + " cells");
      if (!check.note.empty()) study.notes.push_back(check.note);
    }
  }
}

}  // namespace mfwave::wave1d
