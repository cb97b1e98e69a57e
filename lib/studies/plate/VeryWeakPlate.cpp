#include "VeryWeakPlate.hpp"

#include "core/Error.hpp"
#include "core/Stopwatch.hpp"
#include "integrators/TimeStep.hpp"
#include "io/run/ProgressReporter.hpp"
#include "numerics/StableTimeStep.hpp"
#include "methods/very_weak_sph/VeryWeakSphProblem.hpp"
#include "observers/EnergyObserver.hpp"
#include "observers/LinearEnergyLedger.hpp"
#include "observers/StabilityMonitor.hpp"
#include "observers/GroupMeanRecorder.hpp"
#include "observers/TimeLoop.hpp"
#include "particles/BoxFace.hpp"
#include "particles/GhostLayers.hpp"
#include "particles/Lattice.hpp"
#include "wiring/VeryWeakSphRun.hpp"

#include <cmath>

namespace mfwave::plate {
namespace {

constexpr int D = 2;

}  // namespace

PlateCaseResult runVeryWeakPlateCase(const PlateStudy& study, const PlateCaseSettings& settings,
                                     const std::string& folder, bool progress) {
  const Scene& scene = study.scene;
  PlateCaseResult result;
  result.settings = settings;
  const Stopwatch setupClock;
  const Material material = scene.material.material();
  const CantileverPlate plate(study.length, study.thickness, material);

  // the nodal lattice of the plate with two ghost layers on every face
  const Real dx = study.thickness / static_cast<Real>(settings.rows);
  result.spacing = dx;
  const Vec2 lower(0, study.lowerY), upper(study.length, study.lowerY + study.thickness);
  ParticleSet<D> particles = makeLattice<D>(lower, upper, dx);
  if (study.veryWeakGhostLayers > 0)
    addGhostLayers<D>(particles, lower, upper, dx, static_cast<int>(study.veryWeakGhostLayers), allFaces(D));
  const Index n = particles.physicalCount();
  result.record.particles = n;
  result.smoothingLength = study.veryWeakSmoothingLengthRatio * dx;

  // the consistent variant (patch-test exact rows; the state is the nodal displacement), the clamp
  // (both components of the -x face held at zero, eq. (30)) and the second-order smoothing filter
  VeryWeakSphProblemSettings<D> problemSettings;
  problemSettings.options.material = material;
  problemSettings.options.variant = VeryWeakSphVariant::Consistent;
  problemSettings.smoothingLength = result.smoothingLength;
  problemSettings.lower = lower;
  problemSettings.upper = upper;
  problemSettings.spacing = dx;
  problemSettings.prescribed.push_back({faceBit(BoxFace::MinusX), Vec2::Zero(), nullptr});
  problemSettings.smoothingRate = study.veryWeakSmoothingRate;
  problemSettings.smoothingOrder = 2;
  problemSettings.ghostLayers = static_cast<int>(study.veryWeakGhostLayers);
  problemSettings.ghostFaces = allFaces(D);
  // the lattice stencils (issue 18): the same rows without a matrix per particle
  problemSettings.storage = OperatorStorage::Lattice;
  VeryWeakSphProblem<D> problem(particles, problemSettings);
  LinearOperatorSystem& system = problem.system();
  result.meanNeighbours = problem.meanStencilSize();
  result.fixedParticles = static_cast<Index>(problem.prescribedDofs().size()) / D;

  // central differences at a fraction of the operator's stable step
  const StableTimeStep stable = centralDifferenceStableStep(system, 1e-6, 5000);
  const Real stableStep = stable.usable();
  if (!stable.converged)
    result.notes.push_back(settings.name + ": power iteration did not converge; the Gershgorin step is used");
  TimeStepRule rule;  // the step's one home: integrators/TimeStep
  rule.endTime = settings.endTime;
  rule.cfl = study.veryWeakCfl;
  const TimeStepChoice step = chooseTimeStep(rule, stableStep);
  const Real dt = step.dt;
  const std::unique_ptr<CentralDifference> integrator = veryWeakSphCentralDifference<D>(problem);
  Vector v0 = Vector::Zero(D * n);
  for (Index a = 0; a < n; ++a)
    v0[D * a + 1] = plate.initialVelocity(particles.position(a)[0], settings.velocityFactor);
  integrator->initialise(system, 0, Vector::Zero(D * n), v0, dt);

  // the tip: the nodes of the +x face
  std::vector<Index> tipNodes;
  const std::uint8_t plusX = faceBit(BoxFace::PlusX);
  for (Index a = 0; a < n; ++a)
    if (particles.faceMask[static_cast<std::size_t>(a)] & plusX) tipNodes.push_back(a);
  for (Index a : tipNodes) result.tipStartVelocity += v0[D * a + 1];
  result.tipStartVelocity /= static_cast<Real>(tipNodes.size());
  GroupMeanRecorder tip("the plate's tip", tipNodes, D);
  EnergyObserver energy(EnergyObserver::ofLinearSystem(system));
  ProgressReporter reporter(settings.endTime, n, progress);
  // The guards of every linear run: the monitor (non-finite values, grid-scale growth) and the
  // energy ledger, which stops any growth of the free vibration (no loads: quiet from t = 0; the
  // clamp's reactions do no work, the filter only takes energy) with exit 3.
  StabilityMonitor monitor(scene.stability.options(D, 0));
  LinearEnergyLedgerOptions ledgerOptions;
  ledgerOptions.quietAfter = 0;
  ledgerOptions.growthFactor = scene.stability.energyGrowthFactor;
  ledgerOptions.envelopeWindow = 0.5 * plate.period();
  ledgerOptions.balanceLimit = 0;
  ledgerOptions.components = D;
  ledgerOptions.likelyCause = "the very weak SPH's smoothing filter (study.very_weak_smoothing_rate) or step "
                              "(study.very_weak_cfl)";
  ledgerOptions.stop = !scene.stability.allowGrowth;
  LinearEnergyLedger ledger(system, ledgerOptions);
  TimeLoop loop;
  loop.add(monitor);
  loop.add(ledger);
  loop.add(reporter);
  loop.add(tip, study.tipEvery);
  loop.add(energy, study.energyEvery);
  result.record.setupSeconds = setupClock.seconds();

  const RunStatistics stats = loop.run(*integrator, settings.endTime);
  noteAllowedGrowth(result.notes, settings.name, {ledger.growthMessage(), monitor.growthMessage()});
  result.recordLoop(stats);
  result.record.timeStep = dt;
  // 1/2 v^T M v + 1/2 u^T K u: the consistent rows make K slightly non-symmetric, so this is the
  // energy of the symmetric part; its drift is reported as the ledger's balance is for the SPH.
  result.energyDrift = energy.maxRelativeDrift();
  if (problem.smoothing()) {
    const std::vector<Real> total = energy.series().column(2);
    result.viscousFraction = 1 - total.back() / total.front();
  }

  tip.series().writeCsv(folder + "/" + settings.name + "-tip.csv");
  energy.series().writeCsv(folder + "/" + settings.name + "-energy.csv");
  result.files.push_back(settings.name + "-tip.csv");
  result.files.push_back(settings.name + "-energy.csv");
  analyseTip(result, tip.series(), plate, study.shearCoefficient);
  return result;
}

}  // namespace mfwave::plate
