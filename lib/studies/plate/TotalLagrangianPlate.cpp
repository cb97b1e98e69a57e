#include "TotalLagrangianPlate.hpp"

#include "PlateLattice.hpp"

#include "core/Stopwatch.hpp"
#include "integrators/CentralDifference.hpp"
#include "integrators/TimeStep.hpp"
#include "io/run/ProgressReporter.hpp"
#include "io/vtk/FrameOutputs.hpp"
#include "methods/total_lagrangian_sph/TotalLagrangianSph.hpp"
#include "observers/EnergyObserver.hpp"
#include "observers/GroupMeanRecorder.hpp"
#include "observers/StabilityMonitor.hpp"
#include "observers/TimeLoop.hpp"

#include <algorithm>
#include <cmath>

namespace mfwave::plate {
namespace {

constexpr int D = 2;

}  // namespace

PlateCaseResult runTotalLagrangianPlateCase(const PlateStudy& study, const PlateCaseSettings& settings,
                                            const std::string& folder, bool progress) {
  const Scene& scene = study.scene;
  PlateCaseResult result;
  result.settings = settings;
  const Stopwatch setupClock;
  const CantileverPlate plate(study.length, study.thickness, scene.material.material());

  // the particles and the clamp of the updated-Lagrangian cases
  const PlateLattice lattice = sphCaseParticles(study, settings, result);
  const Index n = lattice.particles.physicalCount();

  TotalLagrangianSphOptions options;
  options.material = scene.material.material();
  options.kernel = study.sph.kernel;
  options.smoothingLengthRatio = study.sph.smoothingLengthRatio;
  options.hourglassFactor = study.totalLagrangianHourglass;
  TotalLagrangianSph<D> system(lattice.particles, options);
  system.fixParticles(lattice.clamp);
  result.smoothingLength = system.smoothingLength();
  result.meanNeighbours = system.meanNeighbourCount();

  Vector v0 = firstModeVelocity(lattice, plate, settings.velocityFactor);
  system.clamp(v0);
  for (Index i : lattice.tip) result.tipStartVelocity += v0[i * D + 1];
  result.tipStartVelocity /= static_cast<Real>(lattice.tip.size());

  // central differences at a fraction of the linearised system's limit 2 / omega_max (the step's one
  // home: integrators/TimeStep)
  TimeStepRule rule;
  rule.endTime = settings.endTime;
  rule.cfl = study.totalLagrangianCfl;
  const TimeStepChoice step =
      chooseTimeStep(rule, centralDifferenceStableStep(std::sqrt(system.largestFrequencySquared())));
  const long steps = step.steps;
  const Real dt = step.dt;
  CentralDifference integrator;
  integrator.initialise(system, 0, Vector::Zero(n * D), v0, dt);

  GroupMeanRecorder tip("the plate's tip", lattice.tip, D);
  EnergyObserver energy([&system](const StateView& state) {
    const TotalLagrangianSphEnergy e = system.energy(state.displacement, state.velocity);
    return EnergyTerms{e.kinetic, e.strain + e.hourglass};
  });
  ProgressReporter reporter(settings.endTime, n, progress);
  StabilityMonitor monitor(scene.stability.options(D, 0));
  TimeLoop loop;
  loop.add(monitor);
  loop.add(reporter);
  loop.add(tip, study.tipEvery);
  loop.add(energy, study.energyEvery);
  // Frames of u and v at the reference positions (ParaView: warp by u), when this is the main case.
  typename ParticleFrames<D>::Settings frameOptions = frameSettings<D>(scene.output, settings.writeFrames);
  frameOptions.png = frameOptions.png && study.pngFrames > 0;
  const Real expectedFrames = static_cast<Real>(steps) / static_cast<Real>(scene.output.every);
  frameOptions.pngEvery = std::max(1L, std::lround(expectedFrames / static_cast<Real>(std::max(1L, study.pngFrames))));
  ParticleFrames<D> frames(lattice.particles, folder, settings.name, frameOptions);
  frames.attachTo(loop, scene.output.every);
  result.record.setupSeconds = setupClock.seconds();

  const RunStatistics stats = loop.run(integrator, settings.endTime);
  noteAllowedGrowth(result.notes, settings.name, {monitor.growthMessage()});
  result.recordLoop(stats);
  result.record.timeStep = dt;
  result.energyDrift = energy.maxRelativeDrift();

  tip.series().writeCsv(folder + "/" + settings.name + "-tip.csv");
  energy.series().writeCsv(folder + "/" + settings.name + "-energy.csv");
  result.files.push_back(settings.name + "-tip.csv");
  result.files.push_back(settings.name + "-energy.csv");
  frames.report().appendTo(result.files, result.notes);
  analyseTip(result, tip.series(), plate, study.shearCoefficient);
  return result;
}

}  // namespace mfwave::plate
