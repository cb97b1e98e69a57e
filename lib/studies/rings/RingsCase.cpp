#include "RingsCase.hpp"

#include "numerics/Fragments.hpp"

#include "core/AtomicFile.hpp"
#include "core/Error.hpp"
#include "core/Stopwatch.hpp"
#include "io/run/ProgressReporter.hpp"
#include "io/run/RunSummary.hpp"
#include "io/vtk/FrameOutputs.hpp"
#include "io/vtk/PngFrameRenderer.hpp"
#include "io/vtk/VtkFrameWriter.hpp"
#include "kernels/KernelFactory.hpp"
#include "observers/BodyMotionRecorder.hpp"
#include "observers/PositionSnapshots.hpp"
#include "observers/ProbeRecorder.hpp"
#include "observers/StabilityMonitor.hpp"
#include "observers/StepSizeRecorder.hpp"
#include "observers/TimeLoop.hpp"
#include "observers/TimeSeries.hpp"
#include "particles/Annulus.hpp"
#include "wiring/EnergyLedger.hpp"
#include "wiring/SolidStateAdapter.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <memory>
#include <numeric>
#include <optional>

namespace mfwave::rings {
namespace {

constexpr int D = 2;

// The two rings (concentric circles of particles, makeAnnulus), the left one (centre (-offset, 0))
// first, their outer edges `gap` apart.
ParticleSet<D> makeRings(const StudySettings& study, Index& leftCount) {
  const Real dp = study.scene.geometry.spacing;
  const Real offset = study.centreOffset;
  ParticleSet<D> rings = makeAnnulus(Vec2(-offset, 0), study.innerRadius, study.outerRadius, dp);
  leftCount = rings.physicalCount();
  appendParticles(rings, makeAnnulus(Vec2(offset, 0), study.innerRadius, study.outerRadius, dp));
  return rings;
}

Coordinates<D> positionsOf(const UpdatedLagrangianSphLayout<D>& layout, const Vector& y) {
  Coordinates<D> x;
  for (int a = 0; a < D; ++a) x[static_cast<std::size_t>(a)].resize(static_cast<std::size_t>(layout.particles));
  for (Index i = 0; i < layout.particles; ++i)
    for (int a = 0; a < D; ++a) x[static_cast<std::size_t>(a)][static_cast<std::size_t>(i)] = y[layout.position(i, a)];
  return x;
}

// <case>-rings.csv: each ring's centre of mass (x) and its x velocity, the gap between the rings
// along x (the right ring's leftmost particle minus the left ring's rightmost) and the step.
TimeSeries ringMotion(const std::vector<BodyMotionRecorder<D>::Sample>& samples) {
  TimeSeries series("t [s]", {"x_left [m]", "x_right [m]", "vx_left [m/s]", "vx_right [m/s]", "gap_x [m]", "dt [s]"});
  for (const auto& s : samples)
    series.append(s.time, {s.centre[0][0], s.centre[1][0], s.velocity[0][0], s.velocity[1][0],
                           s.lower[1][0] - s.upper[0][0], s.dt});
  return series;
}

// <case>-positions.csv: every particle at each snapshot time, with its ring and its fragment then.
void writeSnapshots(const std::string& path, const std::vector<PositionSnapshots<D>::Snapshot>& snapshots,
                    Index leftCount, Real linkDistance) {
  AtomicFile file(path);
  std::ostream& out = file.stream();
  out << "t [s],particle,ring,fragment,x [m],y [m]\n" << std::setprecision(9);
  for (const auto& s : snapshots) {
    const std::vector<Index> fragment = findFragments(s.positions, linkDistance).label;
    for (std::size_t i = 0; i < fragment.size(); ++i)
      out << s.time << ',' << i << ',' << (static_cast<Index>(i) < leftCount ? "left" : "right") << ',' << fragment[i]
          << ',' << s.positions[0][i] << ',' << s.positions[1][i] << '\n';
  }
  file.commit();
}

PngOptions pngOptions(const StudySettings& study, Real approachSpeed) {
  const Scene& scene = study.scene;
  PngOptions png = pngOptionsFor(scene.output);
  if (study.autoPointSize) {
    // 0.9 dp on screen: the renderer fits the window's rectangle into the left 80 % of the
    // picture (the colour bar takes the rest) with 12 % to spare.
    const Real halfWidth = 0.5 * (scene.geometry.upper[0] - scene.geometry.lower[0]);
    const Real halfHeight = 0.5 * (scene.geometry.upper[1] - scene.geometry.lower[1]);
    const Real aspect = 0.8 * png.width / png.height;
    const Real pixelsPerMetre = 0.5 * png.height * 0.88 / std::max(halfHeight, halfWidth / aspect);
    png.pointSize = std::clamp(0.9 * scene.geometry.spacing * pixelsPerMetre, 1.0, 40.0);
  }
  // Every picture frames the scene's box (the rings move through it), with one colour scale: the
  // rings' initial speed sets it for the velocity.
  png.window = std::array<Real, 6>{scene.geometry.lower[0], scene.geometry.upper[0], scene.geometry.lower[1],
                                   scene.geometry.upper[1], 0, 0};
  if (png.field == "velocity")
    png.range = png.component == PngOptions::magnitude ? std::array<Real, 2>{0, 2 * approachSpeed}
                                                       : std::array<Real, 2>{-1.5 * approachSpeed, 1.5 * approachSpeed};
  return png;
}

}  // namespace

CaseResult runCase(const StudySettings& study, const CaseSettings& settings, const std::string& folder, bool progress) {
  const Scene& scene = study.scene;
  CaseResult result;
  result.settings = settings;
  CaseRecord& record = result.record;
  record.name = settings.name;
  const Stopwatch setupClock;

  // particles: two rings of concentric particle circles, dp apart
  Index leftCount = 0;
  const ParticleSet<D> particles = makeRings(study, leftCount);
  record.particles = particles.physicalCount();
  result.leftParticles = leftCount;
  result.spacing = scene.geometry.spacing;

  // the method, with or without the artificial stress
  UpdatedLagrangianSphOptions options = study.method;
  options.artificialStress.enabled = settings.artificialStress;
  UpdatedLagrangianSph<D> system(particles, options);
  result.smoothingLength = system.smoothingLength();
  result.supportRadius = makeKernel(options.kernel, D, result.smoothingLength)->supportRadius();
  // Fragments: particles closer than the link distance are joined.
  const Real link = study.linkDistance * result.spacing;
  const std::vector<std::pair<Index, Index>> links = linkPairs(particles.coordinates(), link);
  result.links = static_cast<Index>(links.size());
  const Material& material = options.material;
  result.soundSpeed = std::sqrt(material.bulkModulus() / material.density());
  result.approachSpeed = study.approachSpeed;

  // the rings approach each other along x (the scene's regions' initial velocities)
  Vector velocity = Vector::Zero(record.particles * D);
  for (Index i = 0; i < record.particles; ++i)
    velocity[i * D] = i < leftCount ? result.approachSpeed : -result.approachSpeed;
  const Vector y0 = system.initialState(velocity);
  std::unique_ptr<FirstOrderIntegrator> integrator = makeSolidIntegrator(system, y0, study.integration, scene.integrator.endTime);
  result.firstStep = integrator->stepSize();

  // observers: ledger and ring motion on the whole state; frames, probes and the stability
  // monitor on the particle view of the adapter
  const Real endTime = scene.integrator.endTime;
  EnergyLedger<D> ledger(system);
  std::vector<Real> snapshotTimes;
  for (int k = 0; k < study.snapshots; ++k) snapshotTimes.push_back(endTime * k / std::max(1, study.snapshots - 1));
  // One particle view for every particle output, each at its own interval: the rings' motion,
  // the snapshots, the stability monitor, probes and frames.
  SolidStateAdapter<D> adapter(system, particles);
  std::vector<Index> left(static_cast<std::size_t>(leftCount)), right(static_cast<std::size_t>(record.particles - leftCount));
  std::iota(left.begin(), left.end(), Index(0));
  std::iota(right.begin(), right.end(), leftCount);
  BodyMotionRecorder<D> motion(adapter.particles(), system.masses(), {{"left", left}, {"right", right}});
  adapter.add(motion, study.trackEvery);
  PositionSnapshots<D> snapshots(adapter.particles(), snapshotTimes);
  adapter.add(snapshots);
  StepSizeRecorder steps;
  // A non-linear first-order state: slow growth is the energy ledger's to judge, not the monitor's.
  StabilityMonitorOptions stability = scene.stability.options(D, std::numeric_limits<Real>::infinity());
  StabilityMonitor monitor(stability);
  adapter.add(monitor);
  const std::vector<Probe> probes = resolveProbes(scene.probes, particles);
  ProbeRecorder probeRecorder(probes, D);
  if (!probes.empty()) adapter.add(probeRecorder, scene.output.probeEvery);
  ProgressReporter reporter(endTime, record.particles, progress);

  const ExtraFields methodFields = adapter.extraFields();
  const ExtraFields extra = [&](const StateView& s, Index count, std::vector<ParticleField>& fields) {
    methodFields(s, count, fields);
    std::vector<Real> ring(static_cast<std::size_t>(count));
    for (Index i = 0; i < count; ++i) ring[static_cast<std::size_t>(i)] = i < leftCount ? 0 : 1;
    fields.push_back(ParticleField::scalar("ring", std::move(ring)));
    const Fragments pieces = findFragments(adapter.particles().coordinates(), link);
    std::vector<Real> fragment(pieces.label.begin(), pieces.label.end());
    fields.push_back(ParticleField::scalar("fragment", std::move(fragment)));
  };
  typename ParticleFrames<D>::Settings frameOptions = frameSettings<D>(scene.output, settings.writeFrames);
  frameOptions.pngOptions = pngOptions(study, result.approachSpeed);
  frameOptions.extra = extra;
  ParticleFrames<D> frames(adapter.particles(), folder, settings.name, frameOptions);
  frames.attachTo(adapter, scene.output.every);

  TimeLoop loop;
  loop.add(reporter);
  loop.add(steps);
  loop.add(adapter);
  loop.add(ledger, study.trackEvery);
  record.setupSeconds = setupClock.seconds();

  const Stopwatch runClock;
  try {
    const RunStatistics stats = loop.run(*integrator, endTime);
    result.recordLoop(stats);  // the loop's seconds are the clock's below (set-up of the catch included)
    record.simulatedTime = stats.endTime;
  } catch (const InstabilityError& e) {
    result.failure = e.what();
    record.steps = integrator->stepCount();
    record.simulatedTime = integrator->time();
  }
  record.loopSeconds = runClock.seconds();
  result.rhsEvaluations = integrator->rhsEvaluations();
  result.meanNeighbours = system.meanNeighbourCount();
  result.neighbourRebuilds = system.neighbourRebuilds();
  result.smallestStep = steps.smallest();
  record.timeStep = record.steps > 0 ? record.simulatedTime / static_cast<Real>(record.steps) : 0;

  // energy budget and zero-energy-mode indicators
  const TimeSeries& energy = ledger.series();
  result.initialEnergy = system.energy(y0);
  const Vector& y = integrator->solution();
  const bool finite = y.allFinite();
  if (finite) result.finalEnergy = system.energy(y);
  result.largestBalanceDrift = ledger.largestBalanceDrift();
  const Real scale =
      std::max(result.initialEnergy.kinetic + result.initialEnergy.strain, std::numeric_limits<Real>::min());
  result.finalBalanceDrift = (result.finalEnergy.balance() - result.initialEnergy.balance()) / scale;
  result.largestZigzag = ledger.largestZigzag();
  result.firstZigzagTime = ledger.firstTimeZigzagAbove(study.zigzagThreshold);
  if (energy.rows() > 0) {
    const std::vector<Real> spacing = energy.column(EnergyLedger<D>::MinimumSpacingRatio);
    result.smallestSpacingRatio = *std::min_element(spacing.begin(), spacing.end());
    result.finalSpacingRatio = spacing.back();
  }

  // fragments at the end, and each ring's rebound
  if (finite) {
    const Coordinates<D> positions = positionsOf(system.layout(), y);
    const Fragments pieces = findFragments(positions, link);
    result.fragments = pieces.count();
    result.strayParticles = pieces.particlesOutsideLargest(2);
    result.tornLinks = tornLinks(links, positions, 2 * link);
    for (std::size_t f = 0; f < pieces.sizes.size() && f < 10; ++f) result.fragmentSizes.push_back(pieces.sizes[f]);
  } else {
    result.fragments = -1;
    result.notes.push_back(settings.name + ": the final state is not finite; no fragment count");
  }
  const TimeSeries rings = ringMotion(motion.samples());
  if (rings.rows() > 0) {
    const std::vector<Real> vl = rings.column(2), vr = rings.column(3), gap = rings.column(4);
    result.leftVelocityStart = vl.front();
    result.rightVelocityStart = vr.front();
    result.leftVelocityEnd = vl.back();
    result.rightVelocityEnd = vr.back();
    result.restitutionLeft = -result.leftVelocityEnd / result.leftVelocityStart;
    result.restitutionRight = -result.rightVelocityEnd / result.rightVelocityStart;
    // In contact while the rings are within the kernel's reach of each other; separated once they
    // are out of it for good.
    for (std::size_t k = 0; k < gap.size(); ++k) {
      if (gap[k] < result.supportRadius) {
        if (result.contactTime < 0) result.contactTime = rings.times()[k];
        result.separationTime = -1;
      } else if (result.contactTime >= 0 && result.separationTime < 0) {
        result.separationTime = rings.times()[k];
      }
    }
    result.smallestGap = *std::min_element(gap.begin(), gap.end());
  }

  // files
  energy.writeCsv(folder + "/" + settings.name + "-energy.csv");
  result.files.push_back(settings.name + "-energy.csv");
  rings.writeCsv(folder + "/" + settings.name + "-rings.csv");
  result.files.push_back(settings.name + "-rings.csv");
  writeSnapshots(folder + "/" + settings.name + "-positions.csv", snapshots.snapshots(), leftCount,
                 link);
  result.files.push_back(settings.name + "-positions.csv");
  if (!probes.empty()) {
    probeRecorder.series().writeCsv(folder + "/" + settings.name + "-probes.csv");
    result.files.push_back(settings.name + "-probes.csv");
  }
  frames.report().appendTo(result.files, result.notes);
  if (!result.failure.empty()) result.notes.push_back(settings.name + " stopped early: " + result.failure);
  record.errors = {{"largest_balance_drift", result.largestBalanceDrift},
                   {"extra_fragments", static_cast<Real>(result.fragments - 2)}};
  record.primaryError = "largest_balance_drift";
  record.peakMemoryMiB = peakMemoryMiB();
  return result;
}

}  // namespace mfwave::rings
