#include "PlateCase.hpp"

#include "PlateLattice.hpp"
#include "TotalLagrangianPlate.hpp"
#include "VeryWeakPlate.hpp"

#include "core/Error.hpp"
#include "core/Stopwatch.hpp"
#include "io/run/ProgressReporter.hpp"
#include "io/vtk/FrameOutputs.hpp"
#include "io/vtk/PngFrameRenderer.hpp"
#include "io/vtk/VtkFrameWriter.hpp"
#include "methods/updated_lagrangian_sph/UpdatedLagrangianSph.hpp"
#include "observers/GroupMeanRecorder.hpp"
#include "observers/TimeLoop.hpp"
#include "wiring/EnergyLedger.hpp"
#include "wiring/SolidIntegration.hpp"
#include "wiring/SolidStateAdapter.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>

namespace mfwave::plate {
namespace {

constexpr int D = 2;

PlateCaseResult runUpdatedLagrangianCase(const PlateStudy& study, const PlateCaseSettings& settings,
                                         const std::string& folder, bool progress) {
  const Scene& scene = study.scene;
  PlateCaseResult result;
  result.settings = settings;
  const Stopwatch setupClock;
  const CantileverPlate plate(study.length, study.thickness, scene.material.material());

  // particles: the plate and its clamp, cell-centred
  const PlateLattice lattice = sphCaseParticles(study, settings, result);

  // the method, the clamp, and the first mode's velocity (GMS)
  UpdatedLagrangianSph<D> system(lattice.particles, study.sph);
  system.fixParticles(lattice.clamp);
  result.smoothingLength = system.smoothingLength();
  const Vector y0 = system.initialState(firstModeVelocity(lattice, plate, settings.velocityFactor));
  const auto& layout = system.layout();
  for (Index i : lattice.tip) result.tipStartVelocity += y0[layout.velocity(i, 1)];
  result.tipStartVelocity /= static_cast<Real>(lattice.tip.size());

  // the integrator, with the method's step criteria (times integrator.cfl) before every step
  std::unique_ptr<FirstOrderIntegrator> integrator =
      makeSolidIntegrator(system, y0, solidIntegrationSettings(scene.integrator), settings.endTime,
                          settings.writeFrames ? "integrator.end_time" : "study.convergence_end_time");
  const Real firstStep = study.stepFactor * system.stableStep(y0);

  // observers: tip, energy ledger, frames through the particle view
  // One particle view (u = x - X, v) for the tip and the frames, each at its own interval.
  SolidStateAdapter<D> adapter(system, lattice.particles);
  GroupMeanRecorder tip("the plate's tip", lattice.tip, D);
  adapter.add(tip, study.tipEvery);
  EnergyLedger<D> ledger(system);
  ProgressReporter reporter(settings.endTime, result.record.particles, progress);
  typename ParticleFrames<D>::Settings frameOptions = frameSettings<D>(scene.output, settings.writeFrames);
  frameOptions.png = frameOptions.png && study.pngFrames > 0;
  // About study.pngFrames pictures over the run (rendering costs ~1 s each).
  const Real expectedFrames = settings.endTime / firstStep / static_cast<Real>(scene.output.every);
  frameOptions.pngEvery = std::max(1L, std::lround(expectedFrames / static_cast<Real>(std::max(1L, study.pngFrames))));
  frameOptions.extra = adapter.extraFields();
  ParticleFrames<D> frames(adapter.particles(), folder, settings.name, frameOptions);
  frames.attachTo(adapter, scene.output.every);
  TimeLoop loop;
  loop.add(reporter);
  loop.add(adapter);
  loop.add(ledger, study.energyEvery);
  result.record.setupSeconds = setupClock.seconds();

  const RunStatistics stats = loop.run(*integrator, settings.endTime);
  result.recordLoop(stats);
  result.record.timeStep = stats.steps > 0 ? (stats.endTime - stats.startTime) / static_cast<Real>(stats.steps) : 0;
  result.meanNeighbours = system.meanNeighbourCount();
  result.neighbourRebuilds = system.neighbourRebuilds();

  // the ledger: drift of the balance, where the energy went
  result.energyDrift = ledger.largestBalanceDrift();
  result.largestZigzag = ledger.largestZigzag();
  const TimeSeries& energy = ledger.series();
  const Real initial = ledger.initialEnergy();
  result.viscousFraction = energy.column(EnergyLedger<D>::ViscousDissipation).back() / initial;
  result.artificialStressFraction = energy.column(EnergyLedger<D>::ArtificialStressWork).back() / initial;
  const std::vector<Real> kinetic = energy.column(EnergyLedger<D>::Kinetic);
  const std::vector<Real> zigzag = energy.column(EnergyLedger<D>::Zigzag);
  result.largestZigzagEnergy = 0;
  for (std::size_t k = 0; k < zigzag.size(); ++k)
    result.largestZigzagEnergy = std::max(result.largestZigzagEnergy, zigzag[k] * zigzag[k] * kinetic[k] / initial);
  const std::vector<Real> spacing = energy.column(EnergyLedger<D>::MinimumSpacingRatio);
  result.smallestSpacingRatio = *std::min_element(spacing.begin(), spacing.end());

  tip.series().writeCsv(folder + "/" + settings.name + "-tip.csv");
  energy.writeCsv(folder + "/" + settings.name + "-energy.csv");
  result.files.push_back(settings.name + "-tip.csv");
  result.files.push_back(settings.name + "-energy.csv");
  frames.report().appendTo(result.files, result.notes);
  analyseTip(result, tip.series(), plate, study.shearCoefficient);
  return result;
}

}  // namespace

PlateLattice sphCaseParticles(const PlateStudy& study, const PlateCaseSettings& settings, PlateCaseResult& result) {
  PlateLattice lattice =
      cellCentredPlate(study.length, study.thickness, study.lowerY, settings.rows, study.clampLayers);
  result.spacing = lattice.spacing;
  result.record.particles = lattice.particles.physicalCount();
  result.fixedParticles = static_cast<Index>(lattice.clamp.size());
  return lattice;
}

Vector firstModeVelocity(const PlateLattice& lattice, const CantileverPlate& plate, Real velocityFactor) {
  const Index n = lattice.particles.physicalCount();
  Vector v0 = Vector::Zero(n * D);
  for (Index i = 0; i < n; ++i) v0[i * D + 1] = plate.initialVelocity(lattice.particles.position(i)[0], velocityFactor);
  return v0;
}

void analyseTip(PlateCaseResult& result, const TimeSeries& tip, const CantileverPlate& plate, Real shearCoefficient) {
  result.tip = analyseOscillation(tip.times(), tip.column(1));
  result.thinPeriod = plate.period();
  result.timoshenkoPeriod = plate.timoshenkoPeriod(shearCoefficient);
  constexpr Real pi = kPi;
  result.expectedAmplitude = result.tip.period > 0 ? result.tipStartVelocity * result.tip.period / (2 * pi)
                                                   : std::numeric_limits<Real>::quiet_NaN();
  if (result.tip.halfPeriods < 2)
    result.notes.push_back(result.settings.name + ": fewer than two half periods of the tip were seen; no period");
  CaseRecord& record = result.record;
  record.name = result.settings.name;
  record.simulatedTime = result.settings.endTime;
  record.errors = {{"period_error_thin", result.thinError()},
                   {"period_error_timoshenko", result.timoshenkoError()},
                   {"abs_period_error_timoshenko", std::abs(result.timoshenkoError())}};
  record.primaryError = "abs_period_error_timoshenko";
}

PlateCaseResult runPlateCase(const PlateStudy& study, const PlateCaseSettings& settings, const std::string& folder,
                             bool progress) {
  if (settings.method == PlateMethod::VeryWeak) return runVeryWeakPlateCase(study, settings, folder, progress);
  if (settings.method == PlateMethod::TotalLagrangian)
    return runTotalLagrangianPlateCase(study, settings, folder, progress);
  return runUpdatedLagrangianCase(study, settings, folder, progress);
}

}  // namespace mfwave::plate
