#include "studies/lamb3d/LambRankCase.hpp"

#include "studies/lamb3d/LambCaseLoop.hpp"
#include "studies/lamb3d/LambProbeScores.hpp"

#include "core/Error.hpp"
#include "decomposition/mpi/LatticeShare.hpp"
#include "decomposition/mpi/RankAgreement.hpp"
#include "decomposition/mpi/RankStencilProduct.hpp"
#include "decomposition/mpi/RankProbes.hpp"
#include "integrators/IntegratorFactory.hpp"
#include "io/run/ProgressReporter.hpp"
#include "io/scene/ProbeSpec.hpp"
#include "io/vtk/ParallelVtkFrameWriter.hpp"
#include "observers/StabilityMonitor.hpp"
#include "observers/TimeLoop.hpp"
#include "particles/GhostLayers.hpp"
#include "particles/Lattice.hpp"
#include "wiring/LambReference.hpp"
#include "wiring/VeryWeakSphRun.hpp"

#include <iomanip>
#include <memory>
#include <optional>
#include <sstream>

namespace mfwave::lamb3d {

template <int D>
std::string whyNotOnRanks(const VeryWeakSphProblemSettings<D>& settings, const Scene& scene) {
  if (settings.storage != OperatorStorage::Lattice) return "its operator is an assembled matrix, not lattice stencils";
  // The kernel variants' dashpots may couple particles, beside which the ranks take no prescribed dofs.
  if (!settings.prescribed.empty() && settings.transmittingFaces != 0 &&
      settings.options.variant != VeryWeakSphVariant::Galerkin)
    return "it prescribes displacements beside dashpots of a kernel variant";
  if (scene.integrator.kind == IntegratorKind::Newmark) return "newmark solves with the assembled matrices";
  return {};
}

template <int D>
CaseResult runOnRanks(const StudySettings& study, const CaseSettings& settings, const std::string& folder,
                      bool progress, const VeryWeakSphProblemSettings<D>& problemSettings,
                      const LinearEnergyLedgerOptions& ledgerOptions, CaseResult result, const Stopwatch& setupClock) {
  const Scene& scene = study.scene;
  const GeometrySpec& geometry = settings.geometry;
  const Vec<D>& lower = problemSettings.lower;
  const Vec<D>& upper = problemSettings.upper;
  const Real dx = problemSettings.spacing;

  // The problem from the lattice's description, as the serial case builds it from the particles
  // (eqs. (19), (21)-(22), (31)-(33), (35)), and this rank's share of its system.
  VeryWeakSphProblem<D> problem(problemSettings);
  const LatticeSecondOrderSystem<D>& whole = *problem.latticeSystem();
  const Index nodeCount = whole.stiffness().types().nodeCount();
  result.record.particles = nodeCount;
  result.ghosts = ghostLayerCount<D>(lower, upper, dx, problemSettings.ghostLayers, problemSettings.ghostFaces);
  result.smoothingLength = problem.kernel().smoothingLength();
  result.meanNeighbours = problem.meanStencilSize();
  result.operatorNonZeros = problem.storedStiffnessEntries();
  result.operatorMiB = problem.operatorMiB();
  LatticeShare<D> share(whole, MPI_COMM_WORLD);
  DistributedLatticeSystem<D>& system = share.system();
  const bool first = share.rank() == 0;

  // The serial step, from the power iteration over the shares (bit for bit the serial estimate).
  const Real dt = chooseLambTimeStep(system, scene, "the assembled operator", result);

  // The serial case's integrator, ledger and filter (eq. (33), its product on this rank's share), on
  // this rank's share of the system.
  LinearEnergyLedger ledger(system, ledgerOptions);
  std::optional<RankStencilProduct<D>> smoothingProduct;
  std::unique_ptr<ConservativeSmoothing> smoothing;
  if (const LatticeStencils<D>* stencils = problem.smoothingStencils()) {
    smoothingProduct.emplace(*stencils, share.decomposition(), share.rank(), MPI_COMM_WORLD);
    smoothing = std::make_unique<ConservativeSmoothing>(
        [&smoothingProduct](const Vector& in, Vector& out) {
          out.resize(in.size());
          smoothingProduct->multiply(in.data(), out.data());
        },
        system.size() / D, D, problem.smoothing()->rate(), problem.smoothing()->order());
  }
  // Any other integrator as the serial case makes it (ARKODE on the system's MPI vectors, norms
  // summed in lattice order); checkVeryWeakSphScene refused the filter for them.
  // Prescribed faces (eq. (30), central differences only: checkVeryWeakSphScene): this rank's dofs
  // of the serial list, in its numbering, held at the serial values.
  const std::vector<Index>& serialDofs = problem.prescribedDofs();
  std::vector<Index> prescribed, serialPlace;
  for (std::size_t k = 0; k < serialDofs.size(); ++k) {
    const Index local = share.localNode(serialDofs[k] / D);
    if (local < 0) continue;
    prescribed.push_back(D * local + serialDofs[k] % D);
    serialPlace.push_back(static_cast<Index>(k));
  }
  auto prescribedValues = [&problem, &serialPlace, all = Vector(static_cast<Index>(serialDofs.size()))](
                              Real t, Vector& values) mutable {
    problem.prescribedValues(t, all);
    for (std::size_t k = 0; k < serialPlace.size(); ++k) values[static_cast<Index>(k)] = all[serialPlace[k]];
  };
  std::unique_ptr<SecondOrderIntegrator> integrator;
  if (scene.integrator.kind == IntegratorKind::CentralDifference) {
    std::unique_ptr<CentralDifference> central = smoothedCentralDifference(smoothing.get(), &ledger);
    if (!serialDofs.empty()) central->setPrescribedDisplacement(prescribed, prescribedValues);
    integrator = std::move(central);
  } else {
    integrator = makeSecondOrderIntegrator(scene.integrator.name, scene.integrator.options);
  }
  // At rest, with the prescribed dofs at their values at t = 0 (eq. (30) holds from the start).
  Vector u0 = Vector::Zero(system.size());
  Vector g0(static_cast<Index>(prescribed.size()));
  prescribedValues(0, g0);
  for (std::size_t k = 0; k < prescribed.size(); ++k) u0[prescribed[k]] = g0[static_cast<Index>(k)];
  integrator->initialise(system, 0, u0, Vector::Zero(system.size()), dt);

  // Probes: each placed on its lattice node and read by the rank owning it (a particle's number is
  // its lattice node's), the deconvolved value (eq. (35)) from its row's neighbours wherever they
  // live; each probe's site (position, face tags) is its node's particle alone.
  const std::vector<Probe> probes = resolveProbesOnLattice(scene.probes, geometry);
  std::vector<ProbeSite<D>> sites;
  for (const Probe& p : probes) {
    const std::array<Index, D> node = whole.types().node(p.particle);
    std::array<Index, D> next = node;
    for (Index& n : next) ++n;
    sites.push_back(probeSite<D>(makeLattice<D>(lower, upper, dx, node, next), 0));
  }
  std::vector<Index> probeParticles;
  std::vector<int> probeComponents;
  for (const Probe& p : probes) {
    probeParticles.push_back(p.particle);
    probeComponents.push_back(p.component);
  }
  const ParticleMatrix deconvolutionRows = problem.deconvolutionRows(probeParticles, probeComponents);
  RankProbes recorder(probes, [&share](Index particle) { return share.localNode(particle); }, D, MPI_COMM_WORLD,
                      problem.deconvolves() ? &deconvolutionRows : nullptr);
  result.record.setupSeconds = setupClock.seconds();

  StabilityMonitor monitor(scene.stability.options(D, ledgerOptions.quietAfter));
  ProgressReporter reporter(scene.integrator.endTime, nodeCount, progress && first);
  // The frames: this rank's block of particles, in its state's order.
  std::optional<ParticleSet<D>> block;
  std::optional<ParallelVtkFrameWriter<D>> frames;
  if (settings.writeFrames && scene.output.vtk) {
    block.emplace(makeLattice<D>(lower, upper, dx, system.owned().lo, system.owned().hi));
    std::vector<Index> mine(static_cast<std::size_t>(block->size()));
    for (std::size_t k = 0; k < mine.size(); ++k) mine[k] = static_cast<Index>(k);
    frames.emplace(*block, std::move(mine), folder, settings.name, D, share.rank(), share.ranks());
  }
  TimeLoop loop;
  loop.agreeAcrossRanks(maximumOverRanks(MPI_COMM_WORLD));  // stops and wall-clock checkpoints at one step
  loop.add(monitor);
  loop.add(ledger);
  loop.add(reporter);
  loop.add(recorder, scene.output.probeEvery);
  if (frames) loop.add(*frames, scene.output.every);
  runLambLoopWithLedger(loop, *integrator, scene, recorder, ledger, monitor, folder, result, first);
  // Every piece of the last frame is written before rank 0 reports the series.
  MPI_Barrier(MPI_COMM_WORLD);

  if (first) scoreLambProbes<D>(study, settings, sites, recorder, &problem.kernel(), folder, result);
  const std::array<int, D>& grid = share.decomposition().grid();
  std::ostringstream note;
  note << settings.name << ": stepped on " << share.ranks() << " ranks, blocks ";
  for (int a = 0; a < D; ++a) note << (a ? " x " : "") << grid[static_cast<std::size_t>(a)];
  note << ", cost imbalance " << std::setprecision(3) << share.decomposition().imbalance() << ", halo "
       << system.exchange().bytesSent() << " bytes in " << system.exchange().messagesSent()
       << " messages per step on rank 0";
  result.notes.push_back(note.str());
  if (frames) {
    result.files.push_back(settings.name + ".pvd (" + std::to_string(frames->framesWritten()) + " frames of " +
                           std::to_string(share.ranks()) + " pieces)");
    if (scene.output.png) result.notes.push_back(settings.name + ": no PNG frames on ranks (VTK pieces only)");
  }
  result.record.peakMemoryMiB = peakMemoryMiB();
  return result;
}

#define MFWAVE_LAMB_RANK_CASE(D)                                                                               \
  template std::string whyNotOnRanks<D>(const VeryWeakSphProblemSettings<D>&, const Scene&);                   \
  template CaseResult runOnRanks<D>(const StudySettings&, const CaseSettings&, const std::string&, bool,       \
                                    const VeryWeakSphProblemSettings<D>&, const LinearEnergyLedgerOptions&,   \
                                    CaseResult, const Stopwatch&);
MFWAVE_LAMB_RANK_CASE(2)
MFWAVE_LAMB_RANK_CASE(3)
#undef MFWAVE_LAMB_RANK_CASE

}  // namespace mfwave::lamb3d
