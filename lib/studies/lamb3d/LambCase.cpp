#include "LambCase.hpp"
#include "LambCaseLoop.hpp"
#include "LambCollocationCase.hpp"
#include "LambProbeScores.hpp"
#include "LambSolidCase.hpp"
#include "LambSpectralElementCase.hpp"

#include "core/Error.hpp"
#include "core/Stopwatch.hpp"
#include "integrators/IntegratorFactory.hpp"
#include "io/run/ProgressReporter.hpp"
#include "io/scene/BuildParticles.hpp"
#include "io/scene/Faces.hpp"
#include "io/vtk/FrameOutputs.hpp"
#include "io/vtk/PngFrameRenderer.hpp"
#include "io/vtk/VtkFrameWriter.hpp"
#include "methods/very_weak_sph/VeryWeakSphProblem.hpp"
#include "observers/LinearEnergyLedger.hpp"
#include "observers/StabilityMonitor.hpp"
#include "observers/TimeLoop.hpp"
#include "wiring/VeryWeakSphRun.hpp"
#include "wiring/VeryWeakSphScene.hpp"
#ifdef MFWAVE_WITH_MPI
#include "decomposition/mpi/MpiSession.hpp"
#include "decomposition/mpi/RankCheckpointStore.hpp"
#include "studies/lamb3d/LambRankCase.hpp"
#endif

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <sstream>
#include <string>

namespace mfwave::lamb3d {

namespace {

template <int D>
CaseResult runCaseIn(const StudySettings& study, const CaseSettings& settings, const std::string& folder,
                     bool progress) {
  const Scene& scene = study.scene;
  CaseResult result;
  result.settings = settings;
  CaseRecord& record = result.record;
  record.name = settings.name;
  const Stopwatch assemblyClock;

  // the very weak SPH set-up of the scene, and the energy ledger's options, which also stops growth
  // after the loads (LinearEnergyLedger)
  const VeryWeakSphSpec& spec = settings.method;
  const VeryWeakSphProblemSettings<D> problemSettings =
      veryWeakSphProblemSettings<D>(scene, settings.geometry, spec, !settings.freeFaces);
  const Scene caseScene = [&] {
    Scene s = scene;
    if (settings.freeFaces) s.boundaries.clear();
    return s;
  }();
  // Prescribed displacements do work through reactions the ledger does not see.
  const bool movingFaces = facesWith(caseScene.boundaries, BoundaryType::Displacement) != 0;
  const LinearEnergyLedgerOptions ledgerOptions =
      lambLedgerOptions(caseScene, settings.geometry, D, spec.options.material, movingFaces,
                        veryWeakSphGrowthCause(spec.options.variant));
#ifdef MFWAVE_WITH_MPI
  // Under mpirun the case sets up and steps on the ranks when it can; one that cannot runs on rank
  // 0 alone.
  std::optional<RankZeroAloneLoop> aloneOnRankZero;
  if (MpiSession::size() > 1) {
    const std::string why = whyNotOnRanks<D>(problemSettings, scene);
    if (why.empty())
      return runOnRanks<D>(study, settings, folder, progress, problemSettings, ledgerOptions, std::move(result),
                           assemblyClock);
    // Its time loop is numbered on every rank and checkpointed by rank 0 without the others.
    aloneOnRankZero.emplace();
    if (MpiSession::rank() != 0) return result;
    result.notes.push_back(settings.name + ": ran on rank 0 alone: " + why);
  }
#endif

  // particles, then the whole very weak SPH set-up: neighbours, the operator (eqs. 21-22), mass,
  // dashpots (eqs. 31-32), loads (eq. 19), prescribed faces (eq. 30), smoothing (eq. 33) and
  // deconvolution (eq. 35)
  const ParticleSet<D> particles = buildParticles<D>(settings.geometry);
  record.particles = particles.physicalCount();
  result.ghosts = particles.size() - particles.physicalCount();
  VeryWeakSphProblem<D> problem(particles, problemSettings);
  LinearOperatorSystem& system = problem.system();
  result.smoothingLength = problem.kernel().smoothingLength();
  result.meanNeighbours = problem.meanStencilSize();
  result.operatorNonZeros = problem.storedStiffnessEntries();
  result.operatorMiB = problem.operatorMiB();

  // time step: a fraction of the operator's stable central-difference step (exit 2 above the limit)
  const Real dt = chooseLambTimeStep(system, scene, "the assembled operator", result);

  LinearEnergyLedger ledger(system, ledgerOptions);

  // integrator: central differences with the smoothing (eq. 33) as its velocity filter and eq. (30)
  // for prescribed faces (checkVeryWeakSphScene refused both for any other integrator)
  const std::unique_ptr<SecondOrderIntegrator> integrator =
      scene.integrator.kind == IntegratorKind::CentralDifference
          ? veryWeakSphCentralDifference<D>(problem, &ledger)
          : makeSecondOrderIntegrator(scene.integrator.name, scene.integrator.options);
  // At rest, with the prescribed faces at their values at t = 0 (eq. (30) holds from the start).
  integrator->initialise(system, 0, problem.initialDisplacement(), Vector::Zero(system.size()), dt);

  // observers: stability, probes (raw and deconvolved), frames
  const std::vector<Probe> probes = resolveProbes(scene.probes, particles);
  // the deconvolution's rows at the probes (eq. (35) of what is reported), from either storage
  std::vector<Index> probeParticles;
  std::vector<int> probeComponents;
  for (const Probe& p : probes) {
    probeParticles.push_back(p.particle);
    probeComponents.push_back(p.component);
  }
  const ParticleMatrix deconvolutionRows = problem.deconvolutionRows(probeParticles, probeComponents);
  VeryWeakSphProbes recorder(probes, D, problem.deconvolves() ? &deconvolutionRows : nullptr);
  record.setupSeconds = assemblyClock.seconds();

  StabilityMonitor monitor(scene.stability.options(D, ledgerOptions.quietAfter));
  ProgressReporter reporter(scene.integrator.endTime, particles.physicalCount(), progress);
  ParticleFrames<D> frames(particles, folder, settings.name, frameSettings<D>(scene.output, settings.writeFrames));
  TimeLoop loop;
  loop.add(monitor);
  loop.add(ledger);
  loop.add(reporter);
  loop.add(recorder, scene.output.probeEvery);
  frames.attachTo(loop, scene.output.every);
  runLambLoopWithLedger(loop, *integrator, scene, recorder, ledger, monitor, folder, result);

  // errors against the exact half-space response, the probes' CSV and the figure case's exact.csv
  scoreLambProbes<D>(study, settings, particles, recorder, &problem.kernel(), folder, result);
  frames.report().appendTo(result.files, result.notes);
  record.peakMemoryMiB = peakMemoryMiB();
  return result;
}

}  // namespace

std::string CaseSettings::methodLabel() const {
  if (spectralElementOrder) return "sem N=" + std::to_string(*spectralElementOrder);
  std::ostringstream label;
  if (solid) {
    label << "ul-sph alpha=" << solid->options.viscosity.alpha << " beta=" << solid->options.viscosity.beta
          << (solid->options.kernelGradientCorrection ? " kgc" : "");
    return label.str();
  }
  if (!collocation) return method.variantName();
  label << "rk m=" << collocation->order << " a/h=" << collocation->supportRatio;
  return label.str();
}

namespace {

CaseResult runMethod(const StudySettings& study, const CaseSettings& settings, const std::string& folder,
                     bool progress) {
  if (settings.isCollocation()) return runCollocationCase(study, settings, folder, progress);
  if (settings.isSolid()) return runSolidCase(study, settings, folder, progress);
  if (settings.isSpectralElement()) return runSpectralElementCase(study, settings, folder, progress);
  if (study.scene.info.dimension == 2) return runCaseIn<2>(study, settings, folder, progress);
  if (study.scene.info.dimension == 3) return runCaseIn<3>(study, settings, folder, progress);
  throw InputError("scene.dimension", "the Lamb study runs 2-D and 3-D scenes");
}

}  // namespace

CaseResult runCase(const StudySettings& study, const CaseSettings& settings, const std::string& folder,
                   bool progress) {
#ifdef MFWAVE_WITH_MPI
  // Under mpirun only the very weak SPH steps on the ranks (LambRankCase.hpp); another method's case
  // runs on rank 0 alone, and the other ranks go on to the next case.
  if (MpiSession::size() > 1 && !settings.isVeryWeakSph()) {
    // Its one time loop is numbered on every rank and checkpointed by rank 0 without the others.
    const RankZeroAloneLoop aloneOnRankZero;
    if (MpiSession::rank() != 0) {
      CaseResult skipped;
      skipped.settings = settings;
      skipped.record.name = settings.name;
      return skipped;
    }
    CaseResult result = runMethod(study, settings, folder, progress);
    result.notes.push_back(settings.name + ": ran on rank 0 alone: " + settings.methodLabel() +
                           " is not distributed");
    return result;
  }
#endif
  return runMethod(study, settings, folder, progress);
}

}  // namespace mfwave::lamb3d
