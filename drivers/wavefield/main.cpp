// wavefield: runs any scene with the reference finite-difference discretisation (a scalar wave,
// rho u_tt = (lambda + 2 mu) Lap(u)) on a line, rectangle or block, and writes probes, energy,
// VTK frames and PNG frames as the scene asks. It is the sample of how every study driver is
// wired: scene -> particles + neighbours -> method -> integrator -> observers -> summary.
//
//   wavefield --scene data/scenes/block-ricker.toml [--set key=value ...] [--out DIR]

#include "analysis/StableTimeStep.hpp"
#include "core/Stopwatch.hpp"
#include "core/Error.hpp"
#include "integrators/IntegratorFactory.hpp"
#include "io/run/DriverCommandLine.hpp"
#include "io/run/MemoryGuard.hpp"
#include "io/run/ProgressReporter.hpp"
#include "io/run/RunDriver.hpp"
#include "io/run/SceneDriver.hpp"
#include "io/run/RunSummary.hpp"
#include "io/scene/BuildParticles.hpp"
#include "io/scene/Format.hpp"
#include "io/scene/LoadScene.hpp"
#include "io/scene/StepLimitCheck.hpp"
#include "io/scene/Scene.hpp"
#include "io/vtk/FrameOutputs.hpp"
#include "io/vtk/PngFrameRenderer.hpp"
#include "io/vtk/VtkFrameWriter.hpp"
#include "methods/finite_difference/FiniteDifferenceWaveOperator.hpp"
#include "neighbours/NeighbourList.hpp"
#include "observers/EnergyObserver.hpp"
#include "observers/ProbeRecorder.hpp"
#include "observers/StabilityMonitor.hpp"
#include "observers/TimeLoop.hpp"

#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

using namespace mfwave;

namespace {

const char* kProgram = "wavefield";

// The reference method holds every named face fixed and takes point loads: anything else in the
// scene is a combination it cannot honour, reported against the scene key.
std::uint8_t fixedFaces(const Scene& scene) {
  for (std::size_t i = 0; i < scene.boundaries.size(); ++i)
    if (scene.boundaries[i].type != BoundaryType::Fixed)
      throw InputError("boundary[" + std::to_string(i) + "].type",
                       "the finite_difference method supports only 'fixed' boundaries, got '" +
                           boundaryTypeName(scene.boundaries[i].type) + "'");
  for (std::size_t i = 0; i < scene.loads.size(); ++i)
    if (scene.loads[i].type != LoadType::PointForce)
      throw InputError("load[" + std::to_string(i) + "].type", "the finite_difference method takes point_force loads only");
  return facesWith(scene.boundaries, BoundaryType::Fixed);
}

template <int D>
Index nearestParticle(const ParticleSet<D>& particles, const std::vector<Real>& position) {
  Vec<D> x;
  for (int a = 0; a < D; ++a) x[a] = position[static_cast<std::size_t>(a)];
  Index best = 0;
  Real bestDistance = std::numeric_limits<Real>::infinity();
  for (Index i = 0; i < particles.physicalCount(); ++i) {
    const Real d = (particles.position(i) - x).squaredNorm();
    if (d < bestDistance) {
      bestDistance = d;
      best = i;
    }
  }
  return best;
}

template <int D>
int run(const Scene& scene, const std::string& folder, const DriverOptions& cli) {
  const Stopwatch setup;
  RunSummary summary(kProgram, scene.info.name, scene.method.name, scene.integrator.name);

  // particles + neighbours
  const ParticleSet<D> particles = buildParticles<D>(scene.geometry);
  const Real dx = scene.geometry.spacing;
  const NeighbourList neighbours = buildNeighbourList(CellList<D>(particles, 1.5 * dx));

  // discretisation: the scalar reference with c^2 = (lambda + 2 mu) / rho
  FiniteDifferenceWaveOptions fd;
  fd.spacing = dx;
  fd.density = scene.material.material().density();
  fd.modulus = scene.material.material().pWaveModulus();
  fd.fixedFaces = fixedFaces(scene);
  LinearSecondOrderSystem system = assembleFiniteDifferenceWave(particles, neighbours, fd);

  // loads: each point force acts on the particle nearest its position (the direction is not used
  // by a scalar method)
  std::vector<std::pair<Index, LoadSpec>> pointLoads;
  for (const LoadSpec& load : scene.loads) pointLoads.emplace_back(nearestParticle(particles, load.position), load);
  if (!pointLoads.empty())
    system.setForce([pointLoads](Real t, Vector& f) {
      for (const auto& [particle, load] : pointLoads) f[particle] += load.amplitude * load.timeFunction(t);
    });

  // integrator, with the step a fraction of the operator's stable central-difference step (the
  // Gershgorin bound, exact for this operator; the power-iteration estimate is reported beside it)
  // Every integrator's step is checked against its own limit before any work (exit 2 above it).
  const StableTimeStep stable = centralDifferenceStableStep(system, 1e-6, 2000);
  const Real dt = scene.integrator.timeStepFor(stable.safe());
  const StepLimitCheck check = checkStepLimit(scene.integrator, scene.stability, 2 / stable.safe(), dt, stable.safe(),
                                              "the Gershgorin bound of the operator (exact for this stencil)",
                                              "at dx = " + std::to_string(dx));
  if (!check.note.empty()) summary.notes.add(check.note);
  auto integrator = makeSecondOrderIntegrator(scene.integrator.name, scene.integrator.options);
  const Vector zero = Vector::Zero(system.size());
  integrator->initialise(system, 0, zero, zero, dt);

  // observers
  StabilityMonitor monitor(scene.stability.options(1, loadsQuietAfter(scene)));
  std::vector<Probe> probeList = resolveProbes(scene.probes, particles);
  for (Probe& probe : probeList) probe.component = 0;  // a scalar state has one component
  ProbeRecorder probes(probeList, 1);
  EnergyObserver energy(EnergyObserver::ofLinearSystem(system));
  ProgressReporter progress(scene.integrator.endTime, particles.size(), !cli.quiet);
  typename ParticleFrames<D>::Settings frameOptions = frameSettings<D>(scene.output);
  frameOptions.components = 1;  // a scalar state
  if (frameOptions.pngOptions.component != PngOptions::magnitude) frameOptions.pngOptions.component = 0;
  ParticleFrames<D> frames(particles, folder, "frame", frameOptions);
  TimeLoop loop;
  loop.add(monitor);
  loop.add(progress);
  if (!scene.probes.empty()) loop.add(probes, scene.output.probeEvery);
  if (scene.output.energy) loop.add(energy, scene.output.probeEvery);
  frames.attachTo(loop, scene.output.every);

  const double setupSeconds = setup.seconds();
  const RunStatistics stats = loop.run(*integrator, scene.integrator.endTime);

  // outputs and summary
  if (!scene.probes.empty()) {
    probes.series().writeCsv(folder + "/probes.csv");
    summary.files.add("probes.csv");
  }
  if (scene.output.energy) {
    energy.series().writeCsv(folder + "/energy.csv");
    summary.files.add("energy.csv");
  }
  const FrameOutputReport frameReport = frames.report();
  summary.files.addAll(frameReport.files);
  summary.notes.addAll(frameReport.notes);
  std::vector<std::string> growth;
  noteAllowedGrowth(growth, "", {monitor.growthMessage()});
  summary.notes.addAll(growth);
  summary.particles = particles.size();
  summary.meanNeighbours = neighbours.meanCount();
  summary.steps = stats.steps;
  summary.timeStep = dt;
  summary.simulatedTime = stats.endTime;
  summary.wallSeconds = stats.wallSeconds;
  CaseRecord record;  // one case, no reference: no errors
  record.name = scene.info.name;
  record.particles = summary.particles;
  record.steps = stats.steps;
  record.timeStep = dt;
  record.stableTimeStep = stable.estimate();
  record.simulatedTime = stats.endTime;
  record.setupSeconds = setupSeconds;
  record.loopSeconds = stats.wallSeconds;
  summary.addCase(record);
  summary.figures.push_back({"stable_step_estimate", stable.estimate()});
  summary.figures.push_back({"stable_step_gershgorin", stable.safe()});
  if (scene.output.energy) summary.figures.push_back({"final_total_energy", energy.series().column(2).back()});
  summary.notes.add("no reference solution for this scene: no error reported");
  summary.conclude(folder, &std::cout);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const SceneSchema schema = SceneSchema::common();
  DriverCommandLine cli(kProgram, "wavefield: run a scene with the reference finite-difference scalar wave",
                        schema.describe());
  cli.setDefaultScene("block-ricker.toml");
  if (const auto exit = cli.parse(argc, argv)) return *exit;

  return runDriver(kProgram, [&]() -> int {
    SceneReader reader = loadDriverScene(cli.options(), schema);
    const Scene scene = readScene(reader);
    reader.checkAllKeysRead();  // unknown keys: before any work
    if (scene.method.name != "finite_difference")
      throw InputError("method.name", "wavefield runs the finite_difference method only");
    // 0.7 KiB per particle measured (block-ricker at 68,921 particles: its sparse operator, the state,
    // the probes), doubled for a margin.
    const std::string why = memoryRefusal(
        "geometry.spacing = " + mfwave::scene::formatNumber(scene.geometry.spacing),
        {static_cast<double>(scene.geometry.particleCount()), 1536, "the finite-difference wave, 0.7 KiB measured"});
    if (!why.empty()) reader.fail("geometry.spacing", why);
    const std::string folder = prepareOutputFolder(cli.options(), scene.output.folder, reader);
    switch (scene.geometry.dimension) {
      case 1:
        return run<1>(scene, folder, cli.options());
      case 2:
        return run<2>(scene, folder, cli.options());
      default:
        return run<3>(scene, folder, cli.options());
    }
  });
}
