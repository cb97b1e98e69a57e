#include "LambCase.hpp"
#include "LambCollocationCase.hpp"
#include "LambProbeScores.hpp"
#include "LambSolidCase.hpp"
#include "LambSpectralElementCase.hpp"

#include "analysis/StableTimeStep.hpp"
#include "core/Error.hpp"
#include "core/Stopwatch.hpp"
#include "integrators/IntegratorFactory.hpp"
#include "io/run/ProgressReporter.hpp"
#include "io/scene/BuildParticles.hpp"
#include "io/scene/Faces.hpp"
#include "io/scene/StepLimitCheck.hpp"
#include "io/vtk/FrameOutputs.hpp"
#include "io/vtk/PngFrameRenderer.hpp"
#include "io/vtk/VtkFrameWriter.hpp"
#include "methods/very_weak_sph/VeryWeakSphProblem.hpp"
#include "observers/LinearEnergyLedger.hpp"
#include "observers/StabilityMonitor.hpp"
#include "observers/TimeLoop.hpp"
#include "study/VeryWeakSphRun.hpp"
#include "study/VeryWeakSphScene.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
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

  // particles, then the whole very weak SPH set-up of the scene: neighbours, the operator (eqs.
  // 21-22), mass, dashpots (eqs. 31-32), loads (eq. 19), prescribed faces (eq. 30), smoothing
  // (eq. 33) and deconvolution (eq. 35)
  const ParticleSet<D> particles = buildParticles<D>(settings.geometry);
  record.particles = particles.physicalCount();
  result.ghosts = particles.size() - particles.physicalCount();
  const VeryWeakSphSpec& spec = settings.method;
  VeryWeakSphProblem<D> problem(
      particles, veryWeakSphProblemSettings<D>(scene, settings.geometry, spec, !settings.freeFaces));
  LinearOperatorSystem& system = problem.system();
  result.smoothingLength = problem.kernel().smoothingLength();
  result.meanNeighbours = problem.meanStencilSize();
  result.operatorNonZeros = problem.storedStiffnessEntries();
  result.operatorMiB = problem.operatorMiB();

  // time step: a fraction of the operator's stable central-difference step
  const StableTimeStep stable = centralDifferenceStableStep(system, 1e-6, 5000);
  record.stableTimeStep = stable.estimate();
  result.stableStepGershgorin = stable.safe();
  const Real stableStep = stable.usable();
  if (!stable.converged)
    result.notes.push_back(settings.name + ": power iteration did not converge; the Gershgorin step is used");
  const Real dt = scene.integrator.timeStepFor(stableStep);
  record.timeStep = dt;
  record.simulatedTime = scene.integrator.endTime;
  // The step against the integrator's own limit before any work (exit 2 above it).
  const StepLimitCheck check =
      checkStepLimit(scene.integrator, scene.stability, 2 / stableStep, dt, stableStep,
                     stable.converged ? "a power iteration on the assembled operator" : "the Gershgorin bound",
                     "in case " + settings.name);
  if (!check.note.empty()) result.notes.push_back(check.note);

  // the energy ledger, which also stops growth after the loads (LinearEnergyLedger)
  const Scene caseScene = [&] {
    Scene s = scene;
    if (settings.freeFaces) s.boundaries.clear();
    return s;
  }();
  LinearEnergyLedgerOptions ledgerOptions;
  ledgerOptions.quietAfter = loadsQuietAfter(caseScene);
  // Half the slowest shear period of the block, 4 L / c_s, bounds the envelope's window.
  Real side = 0;
  for (std::size_t a = 0; a < D; ++a) side = std::max(side, settings.geometry.upper[a] - settings.geometry.lower[a]);
  ledgerOptions.envelopeWindow = 2 * side / spec.options.material.sWaveSpeed();
  ledgerOptions.growthFactor = scene.stability.energyGrowthFactor;
  // Prescribed displacements do work through reactions the ledger does not see.
  const bool movingFaces = facesWith(caseScene.boundaries, BoundaryType::Displacement) != 0;
  ledgerOptions.balanceLimit = movingFaces ? 0 : scene.stability.energyBalanceLimit;
  ledgerOptions.components = D;
  ledgerOptions.likelyCause = veryWeakSphGrowthCause(spec.options.variant);
  ledgerOptions.stop = !scene.stability.allowGrowth;
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
  for (const Probe& p : probes) probeParticles.push_back(p.particle);
  const ParticleMatrix deconvolutionRows = problem.deconvolutionRows(probeParticles);
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
  const std::string energyFile = settings.name + "-energy.csv";
  RunStatistics stats;
  try {
    stats = loop.run(*integrator, scene.integrator.endTime);
  } catch (const InstabilityError&) {
    // What was recorded up to the stop stays readable: the probes (without the exact columns) and
    // the energy ledger.
    recorder.writeCsv(folder + "/" + settings.name + "-probes.csv", std::vector<std::vector<Real>>(probes.size()));
    if (scene.output.energy) ledger.series().writeCsv(folder + "/" + energyFile);
    throw;
  }
  result.recordLoop(stats);
  result.energyFinalFraction = ledger.finalEnergyFraction();
  result.energyBalanceDrift = ledger.largestBalanceDrift();
  result.energyGrowth = ledger.growthMessage();
  noteAllowedGrowth(result.notes, settings.name, {result.energyGrowth, monitor.growthMessage()});
  if (scene.output.energy) {
    ledger.series().writeCsv(folder + "/" + energyFile);
    result.files.push_back(energyFile);
  }

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

CaseResult runCase(const StudySettings& study, const CaseSettings& settings, const std::string& folder,
                   bool progress) {
  if (settings.isCollocation()) return runCollocationCase(study, settings, folder, progress);
  if (settings.isSolid()) return runSolidCase(study, settings, folder, progress);
  if (settings.isSpectralElement()) return runSpectralElementCase(study, settings, folder, progress);
  if (study.scene.info.dimension == 2) return runCaseIn<2>(study, settings, folder, progress);
  if (study.scene.info.dimension == 3) return runCaseIn<3>(study, settings, folder, progress);
  throw InputError("scene.dimension", "the Lamb study runs 2-D and 3-D scenes");
}

}  // namespace mfwave::lamb3d
