#include "studies/lamb3d/LambRankCase.hpp"

#include "studies/lamb3d/LambCaseLoop.hpp"
#include "studies/lamb3d/LambProbeScores.hpp"

#include "core/Error.hpp"
#include "decomposition/mpi/LatticeShare.hpp"
#include "decomposition/mpi/RankAgreement.hpp"
#include "decomposition/mpi/RankStencilProduct.hpp"
#include "decomposition/mpi/RankProbes.hpp"
#include "io/run/ProgressReporter.hpp"
#include "io/vtk/ParallelVtkFrameWriter.hpp"
#include "observers/StabilityMonitor.hpp"
#include "observers/TimeLoop.hpp"
#include "study/VeryWeakSphRun.hpp"

#include <iomanip>
#include <memory>
#include <optional>
#include <sstream>

namespace mfwave::lamb3d {

template <int D>
std::string whyNotOnRanks(VeryWeakSphProblem<D>& problem, const Scene& scene) {
  const LatticeSecondOrderSystem<D>* lattice = problem.latticeSystem();
  if (!lattice) return "its operator is an assembled matrix, not lattice stencils";
  if (lattice->hasForce() && !lattice->sparseLoads()) return "its loads are not nonzero entries";
  if (problem.smoothing() && !problem.smoothingStencils()) return "its smoothing filter is an assembled matrix";
  if (!problem.prescribedDofs().empty()) return "it prescribes displacements";
  if (scene.integrator.kind != IntegratorKind::CentralDifference) return "its integrator is not central_difference";
  return {};
}

template <int D>
CaseResult runOnRanks(const StudySettings& study, const CaseSettings& settings, const std::string& folder,
                      bool progress, const ParticleSet<D>& particles, VeryWeakSphProblem<D>& problem, Real dt,
                      const LinearEnergyLedgerOptions& ledgerOptions, CaseResult result,
                      const Stopwatch& setupClock) {
  const Scene& scene = study.scene;
  LatticeShare<D> share(*problem.latticeSystem(), MPI_COMM_WORLD);
  DistributedLatticeSystem<D>& system = share.system();
  const bool first = share.rank() == 0;

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
  const std::unique_ptr<CentralDifference> integrator = smoothedCentralDifference(smoothing.get(), &ledger);
  integrator->initialise(system, 0, system.restrict(problem.initialDisplacement()), Vector::Zero(system.size()), dt);

  // Probes: each read by the rank owning its particle (a particle's number is its lattice node's),
  // the deconvolved value (eq. (35)) from its row's neighbours wherever they live.
  const std::vector<Probe> probes = resolveProbes(scene.probes, particles);
  std::vector<Index> probeParticles;
  for (const Probe& p : probes) probeParticles.push_back(p.particle);
  const ParticleMatrix deconvolutionRows = problem.deconvolutionRows(probeParticles);
  RankProbes recorder(probes, [&share](Index particle) { return share.localNode(particle); }, D, MPI_COMM_WORLD,
                      problem.deconvolves() ? &deconvolutionRows : nullptr);
  result.record.setupSeconds = setupClock.seconds();

  StabilityMonitor monitor(scene.stability.options(D, ledgerOptions.quietAfter));
  ProgressReporter reporter(scene.integrator.endTime, particles.physicalCount(), progress && first);
  std::optional<ParallelVtkFrameWriter<D>> frames;
  if (settings.writeFrames && scene.output.vtk)
    frames.emplace(particles, share.ownedNodes(), folder, settings.name, D, share.rank(), share.ranks());
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

  if (first) scoreLambProbes<D>(study, settings, particles, recorder, &problem.kernel(), folder, result);
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
  template std::string whyNotOnRanks<D>(VeryWeakSphProblem<D>&, const Scene&);                                 \
  template CaseResult runOnRanks<D>(const StudySettings&, const CaseSettings&, const std::string&, bool,       \
                                    const ParticleSet<D>&, VeryWeakSphProblem<D>&, Real,                      \
                                    const LinearEnergyLedgerOptions&, CaseResult, const Stopwatch&);
MFWAVE_LAMB_RANK_CASE(2)
MFWAVE_LAMB_RANK_CASE(3)
#undef MFWAVE_LAMB_RANK_CASE

}  // namespace mfwave::lamb3d
