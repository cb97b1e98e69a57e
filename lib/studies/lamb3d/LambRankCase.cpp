#include "studies/lamb3d/LambRankCase.hpp"

#include "studies/lamb3d/LambCaseLoop.hpp"
#include "studies/lamb3d/LambProbeScores.hpp"

#include "core/Error.hpp"
#include "decomposition/mpi/LatticeShare.hpp"
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
  if (lattice->hasDamping() && !lattice->damping().blockDiagonal()) return "its dashpots couple particles";
  if (lattice->hasForce() && !lattice->sparseLoads()) return "its loads are not nonzero entries";
  if (problem.smoothing()) return "its smoothing filter (method.smoothing_rate) acts on the whole lattice";
  if (problem.deconvolves()) return "its deconvolution (method.deconvolution) reads the whole lattice";
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

  // The serial case's integrator and ledger, on this rank's share of the system.
  LinearEnergyLedger ledger(system, ledgerOptions);
  const std::unique_ptr<CentralDifference> integrator = veryWeakSphCentralDifference<D>(problem, &ledger);
  integrator->initialise(system, 0, system.restrict(problem.initialDisplacement()), Vector::Zero(system.size()), dt);

  // Probes: each read by the rank owning its particle (a particle's number is its lattice node's).
  const std::vector<Probe> probes = resolveProbes(scene.probes, particles);
  std::vector<Index> local;
  for (const Probe& p : probes) local.push_back(share.localNode(p.particle));
  RankProbes recorder(probes, local, D, MPI_COMM_WORLD);
  result.record.setupSeconds = setupClock.seconds();

  StabilityMonitor monitor(scene.stability.options(D, ledgerOptions.quietAfter));
  ProgressReporter reporter(scene.integrator.endTime, particles.physicalCount(), progress && first);
  std::optional<ParallelVtkFrameWriter<D>> frames;
  if (settings.writeFrames && scene.output.vtk)
    frames.emplace(particles, share.ownedNodes(), folder, settings.name, D, share.rank(), share.ranks());
  TimeLoop loop;
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
