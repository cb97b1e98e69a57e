#include "LambCase.hpp"

#include "analysis/StableTimeStep.hpp"
#include "analytic/LambSquareLoad.hpp"
#include "core/AtomicFile.hpp"
#include "core/Error.hpp"
#include "core/Stopwatch.hpp"
#include "integrators/CentralDifference.hpp"
#include "integrators/IntegratorFactory.hpp"
#include "io/run/ProgressReporter.hpp"
#include "io/run/RunSummary.hpp"
#include "io/scene/BuildParticles.hpp"
#include "io/scene/Faces.hpp"
#include "io/scene/StepLimitCheck.hpp"
#include "io/vtk/FrameOutputs.hpp"
#include "io/vtk/PngFrameRenderer.hpp"
#include "io/vtk/VtkFrameWriter.hpp"
#include "kernels/Kernel.hpp"
#include "methods/very_weak_sph/Deconvolution.hpp"
#include "methods/very_weak_sph/VeryWeakSphProblem.hpp"
#include "observers/LinearEnergyLedger.hpp"
#include "observers/StabilityMonitor.hpp"
#include "observers/TimeLoop.hpp"
#include "particles/BoxFace.hpp"
#include "study/VeryWeakSphScene.hpp"

#include <array>
#include <cmath>
#include <iomanip>
#include <memory>
#include <limits>
#include <optional>

namespace mfwave::lamb3d {
namespace {

constexpr int D = 3;

// Every `every` steps: each probe's value in the state and the value the method reports: for the
// published variant the deconvolved value (eq. (35)) from the probe particle's row of the
// deconvolution matrix, else the state itself.
class LambProbes : public Observer {
 public:
  LambProbes(std::vector<Probe> probes, const ParticleMatrix* deconvolution)
      : probes_(std::move(probes)), deconvolution_(deconvolution), raw_(probes_.size()), sharp_(probes_.size()) {}

  void observe(const StateView& s) override {
    if (!times_.empty() && s.time <= times_.back()) return;  // end() right after a sample of the same step
    times_.push_back(s.time);
    for (std::size_t i = 0; i < probes_.size(); ++i) {
      const Vector& field = probes_[i].quantity == ProbeQuantity::Velocity ? s.velocity : s.displacement;
      raw_[i].push_back(field[D * probes_[i].particle + probes_[i].component]);
      sharp_[i].push_back(deconvolution_ ? deconvolveAt(*deconvolution_, probes_[i].particle, field, D,
                                                        probes_[i].component)
                                         : raw_[i].back());
    }
  }
  void end(const StateView& s) override { observe(s); }

  const std::vector<Real>& times() const { return times_; }
  const std::vector<Real>& raw(std::size_t i) const { return raw_[i]; }
  const std::vector<Real>& reported(std::size_t i) const { return sharp_[i]; }

 private:
  std::vector<Probe> probes_;
  const ParticleMatrix* deconvolution_;
  std::vector<Real> times_;
  std::vector<std::vector<Real>> raw_, sharp_;
};

// The exact reference exists for one square surface patch with a normal traction on a Poisson
// (lambda = mu) body, a piecewise-linear load history and probes of the normal velocity or
// displacement on the loaded face. Returns the reason when it does not apply.
std::string exactReferenceProblem(const Scene& scene) {
  if (scene.loads.size() != 1 || scene.loads[0].type != LoadType::SurfacePatch)
    return "the exact reference needs exactly one surface_patch load";
  const LoadSpec& load = scene.loads[0];
  const auto axis = static_cast<std::size_t>(load.face / 2);
  std::vector<Real> widths;
  for (std::size_t a = 0; a < 3; ++a)
    if (a != axis) widths.push_back(load.halfWidth[a]);
  if (std::abs(widths[0] - widths[1]) > 1e-12 * widths[0]) return "the exact reference needs a square patch";
  for (std::size_t a = 0; a < 3; ++a)
    if (a != axis && load.traction[a] != 0) return "the exact reference needs a normal traction";
  const Material material = scene.material.material();
  if (std::abs(material.lambda() - material.mu()) > 1e-12 * material.mu())
    return "the exact reference (Pekeris) needs a Poisson solid, lambda = mu";
  std::vector<Real> times, values;
  if (!load.timeFunction.piecewiseLinear(times, values) || values.front() != 0)
    return "the exact reference needs a piecewise-linear load history starting from 0";
  return "";
}

LambSquareLoad exactReference(const Scene& scene) {
  const LoadSpec& load = scene.loads[0];
  const Material material = scene.material.material();
  std::vector<Real> times, values;
  load.timeFunction.piecewiseLinear(times, values);
  const auto axis = static_cast<std::size_t>(load.face / 2);
  const Real halfWidth = load.halfWidth[(axis + 1) % 3];
  // LambSquareLoad gives the response along the applied traction, i.e. the normal component for
  // traction p n_axis (p of either sign, by linearity).
  return LambSquareLoad(material.mu(), material.sWaveSpeed(), halfWidth, std::move(times), std::move(values),
                        load.traction[axis]);
}

// The exact response at surface point (px, py) relative to the load centre, at each time.
std::vector<Real> exactSeriesAt(const LambSquareLoad& exact, Real px, Real py, const std::vector<Real>& times,
                                bool velocity) {
  std::vector<Real> series;
  for (const Real t : times) series.push_back(velocity ? exact.velocity(px, py, t) : exact.displacement(px, py, t));
  return series;
}

// The exact response to the load spread over the surface by the kernel: the square's response
// averaged over in-plane shifts z with the kernel's plane density int W(z, s) ds (normalised). A
// method whose surface tractions act through W cannot resolve the load more sharply than this.
std::vector<Real> kernelSmoothedExact(const LambSquareLoad& exact, const Kernel& kernel, Real px, Real py,
                                      const std::vector<Real>& times, bool velocity) {
  const Real radius = kernel.supportRadius();
  constexpr int inPlane = 12, normal = 40;
  std::vector<std::array<Real, 3>> shifts;
  Real total = 0;
  for (int i = -inPlane; i <= inPlane; ++i)
    for (int j = -inPlane; j <= inPlane; ++j) {
      const Real zx = radius * i / inPlane, zy = radius * j / inPlane;
      Real density = 0;
      for (int k = -normal; k <= normal; ++k) density += kernel.value(Vec3(zx, zy, radius * k / normal));
      if (density > 0) {
        shifts.push_back({zx, zy, density});
        total += density;
      }
    }
  std::vector<Real> smoothed;
  for (const Real t : times) {
    Real sum = 0;
    for (const auto& [zx, zy, weight] : shifts)
      sum += weight * (velocity ? exact.velocity(px - zx, py - zy, t) : exact.displacement(px - zx, py - zy, t));
    smoothed.push_back(sum / total);
  }
  return smoothed;
}

// What makes this variant's energy grow, for the stop message (docs/theory/very-weak-sph.md).
std::string likelyGrowthCause(VeryWeakSphVariant variant) {
  if (variant == VeryWeakSphVariant::Galerkin)
    return "the galerkin variant's operator is symmetric positive semi-definite and its dashpots dissipative, so its "
           "energy cannot grow at a stable step: look for a step above the stable limit (integrator.cfl) or a defect";
  if (variant == VeryWeakSphVariant::Consistent)
    return "the consistent variant's corrected boundary rows are not symmetric and feed slowly growing modes, "
           "faster as the spacing falls (docs/theory/very-weak-sph.md); method.smoothing_rate only delays it. "
           "stability.allow_growth = true runs on to show it";
  return "the published operator has growing modes (indefinite interior Hessian stencil, non-symmetric boundary "
         "terms) that only its filter (method.smoothing_rate) holds down (docs/theory/very-weak-sph.md). "
         "stability.allow_growth = true runs on to show it";
}

void writeProbes(const std::string& path, const std::vector<Probe>& probes, const LambProbes& recorded,
                 const std::vector<std::vector<Real>>& exact) {
  AtomicFile file(path);
  std::ostream& out = file.stream();
  out << "t [s]";
  for (std::size_t i = 0; i < probes.size(); ++i) {
    out << ',' << probes[i].name << "_raw," << probes[i].name << "_reported";
    if (!exact[i].empty()) out << ',' << probes[i].name << "_exact";
  }
  out << '\n' << std::setprecision(10);
  for (std::size_t k = 0; k < recorded.times().size(); ++k) {
    out << recorded.times()[k];
    for (std::size_t i = 0; i < probes.size(); ++i) {
      out << ',' << recorded.raw(i)[k] << ',' << recorded.reported(i)[k];
      if (!exact[i].empty()) out << ',' << exact[i][k];
    }
    out << '\n';
  }
  file.commit();
}

}  // namespace

CaseResult runCase(const StudySettings& study, const CaseSettings& settings, const std::string& folder,
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
  LinearSecondOrderSystem& system = problem.system();
  result.smoothingLength = problem.kernel().smoothingLength();
  result.meanNeighbours = problem.neighbours().meanCount();
  result.operatorNonZeros = system.stiffness().nonZeros();
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
  ledgerOptions.likelyCause = likelyGrowthCause(spec.options.variant);
  ledgerOptions.stop = !scene.stability.allowGrowth;
  LinearEnergyLedger ledger(system, ledgerOptions);

  // integrator, with the smoothing (eq. 33) as its velocity filter and eq. (30) for prescribed faces
  // (checkVeryWeakSphScene refused both for any other integrator)
  std::unique_ptr<SecondOrderIntegrator> integrator;
  if (scene.integrator.name == "central_difference") {
    auto central = std::make_unique<CentralDifference>();
    if (ConservativeSmoothing* smoothing = problem.smoothing())
      central->setVelocityFilter([smoothing, &ledger](Real step, Vector& v) {
        const Real before = ledger.kineticEnergy(v);
        smoothing->apply(step, v);
        ledger.addFilterLoss(before - ledger.kineticEnergy(v));
      });
    if (!problem.prescribedDofs().empty())
      central->setPrescribedDisplacement(problem.prescribedDofs(),
                                         [&problem](Real t, Vector& values) { problem.prescribedValues(t, values); });
    integrator = std::move(central);
  } else {
    integrator = makeSecondOrderIntegrator(scene.integrator.name, scene.integrator.options);
  }
  // At rest, with the prescribed faces at their values at t = 0 (eq. (30) holds from the start).
  integrator->initialise(system, 0, problem.initialDisplacement(), Vector::Zero(system.size()), dt);

  // observers: stability, probes (raw and deconvolved), frames
  const std::vector<Probe> probes = resolveProbes(scene.probes, particles);
  LambProbes recorder(probes, problem.deconvolution());
  record.setupSeconds = assemblyClock.seconds();

  StabilityMonitor monitor(scene.stability.options(D));
  ProgressReporter reporter(scene.integrator.endTime, particles.physicalCount(), progress);
  std::optional<VtkFrameWriter<D>> frames;
  std::optional<PngFrameRenderer<D>> images;
  TimeLoop loop;
  loop.add(monitor);
  loop.add(ledger);
  loop.add(reporter);
  loop.add(recorder, scene.output.probeEvery);
  if (settings.writeFrames && scene.output.vtk) {
    frames.emplace(particles, folder, settings.name, D);
    loop.add(*frames, scene.output.every);
  }
  if (settings.writeFrames && scene.output.png) {
    images.emplace(particles, folder, settings.name, D, pngOptionsFor(scene.output));
    loop.add(*images, scene.output.every);
  }
  const std::string energyFile = settings.name + "-energy.csv";
  RunStatistics stats;
  try {
    stats = loop.run(*integrator, scene.integrator.endTime);
  } catch (const InstabilityError&) {
    // What was recorded up to the stop stays readable: the probes (without the exact columns) and
    // the energy ledger.
    writeProbes(folder + "/" + settings.name + "-probes.csv", probes, recorder,
                std::vector<std::vector<Real>>(probes.size()));
    if (scene.output.energy) ledger.series().writeCsv(folder + "/" + energyFile);
    throw;
  }
  record.steps = stats.steps;
  record.loopSeconds = stats.wallSeconds;
  result.energyFinalFraction = ledger.finalEnergyFraction();
  result.energyBalanceDrift = ledger.largestBalanceDrift();
  result.energyGrowth = ledger.growthMessage();
  if (!result.energyGrowth.empty())
    result.notes.push_back(settings.name + ": stability.allow_growth let the run go on through: " + result.energyGrowth);
  if (scene.output.energy) {
    ledger.series().writeCsv(folder + "/" + energyFile);
    result.files.push_back(energyFile);
  }

  // errors against the exact half-space response, for probes on the loaded face along its normal
  const std::string referenceProblem = exactReferenceProblem(scene);
  std::optional<LambSquareLoad> exact;
  if (referenceProblem.empty()) exact.emplace(exactReference(scene));
  else result.notes.push_back(referenceProblem);
  std::vector<std::vector<Real>> exactSeries(probes.size());
  std::vector<std::array<Real, 2>> surfacePoint(probes.size());  // probe relative to the load centre, in the face
  for (std::size_t i = 0; i < probes.size(); ++i) {
    ProbeResult r;
    r.name = probes[i].name;
    if (exact) {
      const LoadSpec& load = scene.loads[0];
      const int axis = load.face / 2;
      const Vec<D> x = particles.position(probes[i].particle);
      const bool onFace = (particles.faceMask[static_cast<std::size_t>(probes[i].particle)] & faceBit(load.face)) != 0;
      if (onFace && probes[i].component == axis) {
        const Real px = x[(axis + 1) % 3] - load.centre[static_cast<std::size_t>((axis + 1) % 3)];
        const Real py = x[(axis + 2) % 3] - load.centre[static_cast<std::size_t>((axis + 2) % 3)];
        surfacePoint[i] = {px, py};
        exactSeries[i] = exactSeriesAt(*exact, px, py, recorder.times(), probes[i].quantity == ProbeQuantity::Velocity);
        r.hasExact = true;
        r.raw = compareSignals(recorder.times(), recorder.raw(i), exactSeries[i], study.errorWindow,
                               study.arrivalFraction);
        r.reported = compareSignals(recorder.times(), recorder.reported(i), exactSeries[i], study.errorWindow,
                                    study.arrivalFraction);
        if (study.kernelFloor)
          r.kernelFloor = compareSignals(recorder.times(),
                                         kernelSmoothedExact(*exact, problem.kernel(), px, py, recorder.times(),
                                                             probes[i].quantity == ProbeQuantity::Velocity),
                                         exactSeries[i], study.errorWindow, study.arrivalFraction)
                              .relativeL2;
      } else {
        result.notes.push_back("probe " + r.name + ": no exact reference (not the normal component on the loaded face)");
      }
    }
    result.probes.push_back(r);
  }
  // The record's primary error: the largest reported relative L2 error over the probes with an exact response.
  Real largest = -1;
  for (const ProbeResult& p : result.probes)
    if (p.hasExact) {
      record.errors.push_back({p.name + "_relative_l2", p.reported.relativeL2});
      largest = std::max(largest, p.reported.relativeL2);
    }
  if (largest >= 0) {
    record.errors.push_back({"largest_relative_l2", largest});
    record.primaryError = "largest_relative_l2";
  }
  writeProbes(folder + "/" + settings.name + "-probes.csv", probes, recorder, exactSeries);
  if (exact && settings.writeFrames) {
    // The exact response on a fine time grid, for the figures (the errors use the run's samples).
    constexpr int samples = 600;
    std::vector<Real> times;
    for (int k = 0; k <= samples; ++k) times.push_back(scene.integrator.endTime * k / samples);
    std::vector<std::vector<Real>> columns(probes.size());
    for (std::size_t i = 0; i < probes.size(); ++i)
      if (result.probes[i].hasExact)
        columns[i] = exactSeriesAt(*exact, surfacePoint[i][0], surfacePoint[i][1], times,
                                   probes[i].quantity == ProbeQuantity::Velocity);
    AtomicFile file(folder + "/exact.csv");
    file.stream() << "t [s]";
    for (std::size_t i = 0; i < probes.size(); ++i)
      if (result.probes[i].hasExact) file.stream() << ',' << probes[i].name << "_exact";
    file.stream() << '\n' << std::setprecision(10);
    for (std::size_t k = 0; k < times.size(); ++k) {
      file.stream() << times[k];
      for (std::size_t i = 0; i < probes.size(); ++i)
        if (result.probes[i].hasExact) file.stream() << ',' << columns[i][k];
      file.stream() << '\n';
    }
    file.commit();
    result.files.push_back("exact.csv");
  }
  result.files.push_back(settings.name + "-probes.csv");
  frameOutputReport(settings.name, frames, images).appendTo(result.files, result.notes);
  record.peakMemoryMiB = peakMemoryMiB();
  return result;
}

}  // namespace mfwave::lamb3d
