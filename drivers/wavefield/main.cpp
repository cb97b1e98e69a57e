// wavefield: runs any scene with the reference finite-difference discretisation (a scalar wave,
// rho u_tt = (lambda + 2 mu) Lap(u)) on a line, rectangle or block, and writes probes, energy,
// VTK frames and PNG frames as the scene asks. It is the sample of how every study driver is
// wired: scene -> lattice -> method (stencils) -> integrator -> observers -> summary.
//
//   wavefield --scene data/scenes/block-ricker.toml [--set key=value ...] [--out DIR]
//   mpirun -np 2 wavefield ...   (each rank steps a block of the lattice; the same numbers)

#include "numerics/StableTimeStep.hpp"
#include "core/Stopwatch.hpp"
#include "core/Error.hpp"
#include "core/Interruption.hpp"
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
#include "methods/finite_difference/FiniteDifferenceLattice.hpp"
#include "particles/Lattice.hpp"
#include "observers/EnergyObserver.hpp"
#include "observers/ProbeRecorder.hpp"
#include "observers/StabilityMonitor.hpp"
#include "observers/TimeLoop.hpp"

#ifdef MFWAVE_WITH_MPI
#include "decomposition/mpi/LatticeShare.hpp"
#include "decomposition/mpi/MpiSession.hpp"
#include "decomposition/mpi/RankAgreement.hpp"
#include "decomposition/mpi/RankCheckpointStore.hpp"
#include "decomposition/mpi/RankProbes.hpp"
#include "io/vtk/ParallelVtkFrameWriter.hpp"
#endif

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

// The geometry's lattice: buildParticles numbers its nodes x fastest, as the lattice stencils do.
template <int D>
std::array<Index, D> latticeNodes(const GeometrySpec& geometry) {
  const std::array<Index, D> intervals = latticeIntervals<D>(Eigen::Map<const Vec<D>>(geometry.lower.data()),
                                                             Eigen::Map<const Vec<D>>(geometry.upper.data()),
                                                             geometry.spacing);
  std::array<Index, D> nodes{};
  for (int a = 0; a < D; ++a) nodes[static_cast<std::size_t>(a)] = intervals[static_cast<std::size_t>(a)] + 1;
  return nodes;
}

template <int D>
int run(const Scene& scene, const std::string& folder, const DriverOptions& cli) {
  const Stopwatch setup;
  RunSummary summary(kProgram, scene.info.name, scene.method.name, scene.integrator.name);

  // the box lattice, described by its corners: a rank builds only its own block's particles
  if (scene.geometry.ghostLayers > 0 && scene.geometry.ghostFaces != 0)
    throw InputError("geometry.ghost_layers", "the finite_difference method takes no ghost particles");
  const Real dx = scene.geometry.spacing;
  const Vec<D> lower = Eigen::Map<const Vec<D>>(scene.geometry.lower.data());
  const Vec<D> upper = Eigen::Map<const Vec<D>>(scene.geometry.upper.data());
  const std::array<Index, D> nodes = latticeNodes<D>(scene.geometry);
  Index nodeCount = 1;
  for (Index n : nodes) nodeCount *= n;

  // discretisation: the scalar reference with c^2 = (lambda + 2 mu) / rho, as lattice stencils
  // (nothing stored per particle). Each point force acts on the particle nearest its position (the
  // direction is not used by a scalar method).
  FiniteDifferenceWaveOptions fd;
  fd.spacing = dx;
  fd.density = scene.material.material().density();
  fd.modulus = scene.material.material().pWaveModulus();
  fd.fixedFaces = fixedFaces(scene);
  std::vector<SparseLoad> loads;
  for (const LoadSpec& load : scene.loads)
    loads.push_back({{nearestLatticeNode<D>(lower, upper, dx, Eigen::Map<const Vec<D>>(load.position.data()))},
                     {load.amplitude},
                     &load.timeFunction});
  LatticeSecondOrderSystem<D, 1> serial = finiteDifferenceLatticeSystem<D>(nodes, fd, loads);

  // Under mpirun each rank steps its block of the lattice (LatticeShare): every row, probe and
  // energy is the serial run's bit for bit; rank 0 writes the tables and the summary.
  LinearOperatorSystem* system = &serial;
  int rank = 0, ranks = 1;
#ifdef MFWAVE_WITH_MPI
  std::optional<LatticeShare<D, 1>> share;
  if (MpiSession::size() > 1) {
    share.emplace(serial, MPI_COMM_WORLD);
    system = &share->system();
    rank = share->rank();
    ranks = share->ranks();
  }
#endif
  const bool writer = rank == 0;

  // integrator, with the step a fraction of the operator's stable central-difference step (the
  // Gershgorin bound, exact for this operator; the power-iteration estimate is reported beside it),
  // both over the ranks' shares on ranks (the serial figures, bit for bit).
  // Every integrator's step is checked against its own limit before any work (exit 2 above it).
  const StableTimeStep stable = centralDifferenceStableStep(*system, 1e-6, 2000);
  const Real dt = scene.integrator.timeStepFor(stable.safe());
  const StepLimitCheck check = checkStepLimit(scene.integrator, scene.stability, 2 / stable.safe(), dt, stable.safe(),
                                              "the Gershgorin bound of the operator (exact for this stencil)",
                                              "at dx = " + std::to_string(dx));
  if (!check.note.empty()) summary.notes.add(check.note);
  auto integrator = makeSecondOrderIntegrator(scene.integrator.name, scene.integrator.options);
  const Vector zero = Vector::Zero(system->size());
  integrator->initialise(*system, 0, zero, zero, dt);

  // observers
  StabilityMonitor monitor(scene.stability.options(1, loadsQuietAfter(scene)));
  std::vector<Probe> probeList = resolveProbesOnLattice(scene.probes, scene.geometry);
  for (Probe& probe : probeList) probe.component = 0;  // a scalar state has one component
  EnergyObserver energy(EnergyObserver::ofLinearSystem(*system));
  ProgressReporter progress(scene.integrator.endTime, nodeCount, !cli.quiet && writer);
  TimeLoop loop;
  loop.add(monitor);
  loop.add(progress);
  if (scene.output.energy) loop.add(energy, scene.output.probeEvery);
  std::optional<ProbeRecorder> probes;
  std::optional<ParticleSet<D>> particles;  // for the frames: the whole lattice, or a rank's block
  std::optional<ParticleFrames<D>> frames;
#ifdef MFWAVE_WITH_MPI
  std::optional<RankProbes> rankProbes;
  std::optional<ParallelVtkFrameWriter<D>> pieces;
  if (share) {
    loop.agreeAcrossRanks(maximumOverRanks(MPI_COMM_WORLD));  // stops and wall-clock checkpoints at one step
    rankProbes.emplace(probeList, [&share](Index particle) { return share->localNode(particle); }, 1, MPI_COMM_WORLD);
    rankProbes->sampleAtEnd(false);  // the serial recorder's rows
    if (!scene.probes.empty()) loop.add(*rankProbes, scene.output.probeEvery);
    if (scene.output.vtk) {
      const Box<D>& owned = share->system().owned();
      particles.emplace(makeLattice<D>(lower, upper, dx, owned.lo, owned.hi));
      std::vector<Index> mine(static_cast<std::size_t>(particles->size()));
      for (std::size_t k = 0; k < mine.size(); ++k) mine[k] = static_cast<Index>(k);
      pieces.emplace(*particles, std::move(mine), folder, "frame", 1, rank, ranks);
      loop.add(*pieces, scene.output.every);
    }
  }
#endif
  if (ranks == 1) {
    probes.emplace(probeList, 1);
    if (!scene.probes.empty()) loop.add(*probes, scene.output.probeEvery);
  }
  if (ranks == 1 && (scene.output.vtk || scene.output.png)) {  // the particles only for the frames
    typename ParticleFrames<D>::Settings frameOptions = frameSettings<D>(scene.output);
    frameOptions.components = 1;  // a scalar state
    if (frameOptions.pngOptions.component != PngOptions::magnitude) frameOptions.pngOptions.component = 0;
    particles.emplace(buildParticles<D>(scene.geometry));
    frames.emplace(*particles, folder, "frame", frameOptions);
    frames->attachTo(loop, scene.output.every);
  }

  const double setupSeconds = setup.seconds();
  const RunStatistics stats = loop.run(*integrator, scene.integrator.endTime);
#ifdef MFWAVE_WITH_MPI
  if (share) MPI_Barrier(MPI_COMM_WORLD);  // every piece of the last frame is written
#endif
  if (!writer) return 0;

  // outputs and summary
  if (!scene.probes.empty()) {
    if (probes) {
      probes->series().writeCsv(folder + "/probes.csv");
    } else {
#ifdef MFWAVE_WITH_MPI
      TimeSeries table("time [s]", probeColumnNames(probeList, 1, "s", "m"));
      for (std::size_t k = 0; k < rankProbes->times().size(); ++k) {
        std::vector<Real> row;
        for (std::size_t i = 0; i < probeList.size(); ++i) row.push_back(rankProbes->raw(i)[k]);
        table.append(rankProbes->times()[k], row);
      }
      table.writeCsv(folder + "/probes.csv");
#endif
    }
    summary.files.add("probes.csv");
  }
  if (scene.output.energy) {
    energy.series().writeCsv(folder + "/energy.csv");
    summary.files.add("energy.csv");
  }
  if (frames) {
    const FrameOutputReport frameReport = frames->report();
    summary.files.addAll(frameReport.files);
    summary.notes.addAll(frameReport.notes);
  }
#ifdef MFWAVE_WITH_MPI
  if (share) {
    const std::array<int, D>& grid = share->decomposition().grid();
    std::string blocks;
    for (int a = 0; a < D; ++a) blocks += (a ? " x " : "") + std::to_string(grid[static_cast<std::size_t>(a)]);
    summary.notes.add("stepped on " + std::to_string(ranks) + " ranks (MPI), blocks " + blocks + ", halo " +
                      std::to_string(share->system().exchange().bytesSent()) + " bytes in " +
                      std::to_string(share->system().exchange().messagesSent()) + " messages per step on rank 0");
    if (pieces) summary.files.add("frame.pvd (" + std::to_string(pieces->framesWritten()) + " frames of " +
                                  std::to_string(ranks) + " pieces)");
    if (scene.output.png) summary.notes.add("no PNG frames on ranks (VTK pieces only)");
  }
#endif
  std::vector<std::string> growth;
  noteAllowedGrowth(growth, "", {monitor.growthMessage()});
  summary.notes.addAll(growth);
  summary.particles = nodeCount;
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
  summary.figures.push_back({"operator_bytes", static_cast<Real>(serial.bytes())});
  if (scene.output.energy) summary.figures.push_back({"final_total_energy", energy.series().column(2).back()});
  summary.notes.add("operator: finite-difference lattice stencils, " + std::to_string(serial.stiffness().typeCount()) +
                    " row types, " + std::to_string(serial.bytes()) + " bytes in all");
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
#ifdef MFWAVE_WITH_MPI
  const MpiSession mpi(argc, argv);  // only under a launcher: a plain run starts no MPI
  const int rank = MpiSession::rank(), ranks = MpiSession::size();
#else
  const int rank = 0, ranks = 1;
#endif
  if (const auto exit = cli.parse(argc, argv)) return *exit;

  const int code = runDriver(kProgram, [&]() -> int {
    SceneReader reader = loadDriverScene(cli.options(), schema);
    const Scene scene = readScene(reader);
    reader.checkAllKeysRead();  // unknown keys: before any work
    if (scene.method.name != "finite_difference")
      throw InputError("method.name", "wavefield runs the finite_difference method only");
    // 52 bytes per node measured without frames (block-ricker at dx = 0.005, 8.1 x 10^6 nodes: the
    // state, the stable-step estimate's vectors; the lattice stencils are 15 kB), 56 more for the
    // particles of the frames, doubled and rounded up; a rank holds its share (286 MiB per rank
    // on 2 ranks, MPI's own buffers included).
    const std::string why = memoryRefusal(
        "geometry.spacing = " + mfwave::scene::formatNumber(scene.geometry.spacing),
        {static_cast<double>(scene.geometry.particleCount()) / ranks, 256,
         "the finite-difference wave on lattice stencils, 52 bytes measured, 108 with frames"});
    if (!why.empty()) reader.fail("geometry.spacing", why);
#ifdef MFWAVE_WITH_MPI
    const CheckpointStoreMaker storeMaker = rankAwareCheckpointStoreMaker();  // per rank on several ranks
#else
    const CheckpointStoreMaker storeMaker;
#endif
    const std::string folder = prepareOutputFolder(cli.options(), scene.output.folder, reader, storeMaker);
    switch (scene.geometry.dimension) {
      case 1:
        return run<1>(scene, folder, cli.options());
      case 2:
        return run<2>(scene, folder, cli.options());
      default:
        return run<3>(scene, folder, cli.options());
    }
  }, rank);
#ifdef MFWAVE_WITH_MPI
  // A rank that failed must not leave the others waiting in a halo exchange.
  // An agreed interruption (130, 143) is no failure: every rank stops at the same step and rank 0
  // writes its tables; only then do they exit.
  if (code != 0 && !interruptionRequested()) MpiSession::abortOthers(code);
#endif
  return code;
}
