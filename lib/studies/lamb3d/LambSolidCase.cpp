#include "studies/lamb3d/LambSolidCase.hpp"

#include "core/Error.hpp"
#include "core/Stopwatch.hpp"
#include "io/run/ProgressReporter.hpp"
#include "io/scene/BuildParticles.hpp"
#include "io/scene/Format.hpp"
#include "methods/updated_lagrangian_sph/UpdatedLagrangianSph.hpp"
#include "observers/ReportedProbes.hpp"
#include "observers/StabilityMonitor.hpp"
#include "observers/TimeLoop.hpp"
#include "particles/BoxFace.hpp"
#include "studies/lamb3d/LambProbeScores.hpp"
#include "studies/lamb3d/LambReflection.hpp"
#include "study/SolidIntegration.hpp"
#include "study/SolidStateAdapter.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <memory>
#include <sstream>
#include <utility>

namespace mfwave::lamb3d {

namespace {

constexpr int D = 2;

// The probes of the particle view (SolidStateAdapter: u = x - X, v) divided by the amplitude eps,
// so that they read the linear problem's unit-load response. Raw and reported are the same value.
class SolidProbes : public ReportedProbes {
 public:
  SolidProbes(std::vector<Probe> probes, Real amplitude) : ReportedProbes(std::move(probes)), amplitude_(amplitude) {}

  void observe(const StateView& s) override {
    if (!beginSample(s.time)) return;
    for (std::size_t i = 0; i < probes().size(); ++i) {
      const Probe& p = probes()[i];
      const Vector& field = p.quantity == ProbeQuantity::Velocity ? s.velocity : s.displacement;
      const Real value = field[p.particle * D + p.component] / amplitude_;
      add(i, value, value);
    }
  }

 private:
  Real amplitude_;
};

}  // namespace

Real StripTraction::totalLength() const {
  Real total = 0;
  for (Real l : lengths) total += l;
  return total;
}

StripTraction stripTraction(const LoadSpec& load, const ParticleSet<2>& particles, Real dx) {
  const auto along = static_cast<std::size_t>(1 - faceAxis(load.face));
  const Real patchLower = load.centre[along] - load.halfWidth[along];
  const Real patchUpper = load.centre[along] + load.halfWidth[along];
  // The face's extent along the patch: the lattice's first and last positions.
  Real faceLower = std::numeric_limits<Real>::infinity(), faceUpper = -faceLower;
  for (Index i = 0; i < particles.physicalCount(); ++i) {
    const Real x = particles.position(i)[static_cast<Index>(along)];
    faceLower = std::min(faceLower, x);
    faceUpper = std::max(faceUpper, x);
  }
  StripTraction strip;
  for (Index i = 0; i < particles.physicalCount(); ++i) {
    if ((particles.faceMask[static_cast<std::size_t>(i)] & faceBit(load.face)) == 0) continue;
    const Real x = particles.position(i)[static_cast<Index>(along)];
    // The particle's tributary segment of the face, inside the patch.
    const Real lower = std::max({x - dx / 2, faceLower, patchLower});
    const Real upper = std::min({x + dx / 2, faceUpper, patchUpper});
    if (upper - lower <= 1e-12 * dx) continue;
    strip.particles.push_back(i);
    strip.lengths.push_back(upper - lower);
  }
  return strip;
}

ParticleSet<2> lambSolidParticles(const GeometrySpec& geometry, bool tributaryVolumes) {
  // the very weak SPH case's lattice without its ghosts, which the method refuses (its faces are free)
  GeometrySpec lattice = geometry;
  lattice.ghostLayers = 0;
  lattice.ghostFaces = 0;
  ParticleSet<2> particles = buildParticles<2>(lattice);
  if (tributaryVolumes)
    for (Index i = 0; i < particles.physicalCount(); ++i)
      particles.volume[static_cast<std::size_t>(i)] *= std::pow(0.5, particles.facetCount(i));
  return particles;
}

UpdatedLagrangianSphOptions lambSolidOptions(const LambSolidSpec& spec, const ParticleSet<2>& particles, Real dx) {
  // The method takes its spacing as the D-th root of the mean volume, which the tributary volumes of
  // the faces make smaller than dx: the ratio is rescaled so that h = ratio * dx.
  Real total = 0;
  for (Index i = 0; i < particles.physicalCount(); ++i) total += particles.volume[static_cast<std::size_t>(i)];
  const Real meanSpacing = std::sqrt(total / static_cast<Real>(particles.physicalCount()));
  UpdatedLagrangianSphOptions options = spec.options;
  options.smoothingLengthRatio = spec.options.smoothingLengthRatio * dx / meanSpacing;
  return options;
}

void applyStripLoad(UpdatedLagrangianSph<2>& system, const LoadSpec& load, const StripTraction& strip, Real amplitude) {
  const Vec<D> traction(amplitude * load.traction[0], amplitude * load.traction[1]);
  for (std::size_t k = 0; k < strip.particles.size();) {
    // one traction group per run of equal lengths (the inner particles share dx)
    std::size_t end = k + 1;
    const Real length = strip.lengths[k];
    while (end < strip.particles.size() && std::abs(strip.lengths[end] - length) <= 1e-12 * length) ++end;
    system.addTraction(std::vector<Index>(strip.particles.begin() + static_cast<std::ptrdiff_t>(k),
                                          strip.particles.begin() + static_cast<std::ptrdiff_t>(end)),
                       traction, load.timeFunction, strip.lengths[k]);
    k = end;
  }
}

CaseResult runSolidCase(const StudySettings& study, const CaseSettings& settings, const std::string& folder,
                        bool progress) {
  const Scene& scene = study.scene;
  if (scene.info.dimension != D)
    throw InputError("method.name", "the updated-Lagrangian SPH runs the 2-D Lamb problem (lamb2d) only");
  if (scene.loads.size() != 1 || scene.loads[0].type != LoadType::SurfacePatch)
    throw InputError("load", "the updated-Lagrangian SPH case needs exactly one surface_patch load");
  const LambSolidSpec& spec = *settings.solid;
  const Real eps = spec.amplitude;
  CaseResult result;
  result.settings = settings;
  CaseRecord& record = result.record;
  record.name = settings.name;
  const Stopwatch setupClock;

  const ParticleSet<D> physical = lambSolidParticles(settings.geometry, spec.tributaryVolumes);
  record.particles = physical.physicalCount();
  UpdatedLagrangianSph<D> system(physical, lambSolidOptions(spec, physical, settings.geometry.spacing));
  result.smoothingLength = system.smoothingLength();
  const LoadSpec& load = scene.loads[0];
  const StripTraction strip = stripTraction(load, physical, settings.geometry.spacing);
  applyStripLoad(system, load, strip, eps);
  const Vector y0 = system.initialState();

  // leapfrog at the method's own step criteria, recomputed every step (cfl 1: courant 0.3 is in them)
  SolidIntegrationSettings integration;
  integration.integrator = "leapfrog";
  integration.cfl = 1;
  const std::unique_ptr<FirstOrderIntegrator> integrator =
      makeSolidIntegrator(system, y0, integration, scene.integrator.endTime);
  record.stableTimeStep = system.stableStep(y0);
  record.simulatedTime = scene.integrator.endTime;

  const std::vector<Probe> probes = resolveProbes(scene.probes, physical);
  SolidStateAdapter<D> adapter(system, physical);
  SolidProbes recorder(probes, eps);
  StabilityMonitor monitor(scene.stability.options(D, loadsQuietAfter(scene)));
  adapter.add(monitor, 1);
  adapter.add(recorder, scene.output.probeEvery);
  ProgressReporter reporter(scene.integrator.endTime, record.particles, progress);
  TimeLoop loop;
  loop.add(reporter);
  loop.add(adapter);
  record.setupSeconds = setupClock.seconds();

  // What the case is, and where its free faces start to matter.
  std::ostringstream what;
  what << std::setprecision(4) << settings.name << ": updated-Lagrangian SPH (" << spec.options.kernel
       << ", h / dx = " << spec.options.smoothingLengthRatio << ", continuity density, gamma = 1 EOS, Jaumann rate; "
       << "artificial viscosity alpha = " << spec.options.viscosity.alpha << ", beta = " << spec.options.viscosity.beta
       << "; artificial stress off, XSPH off, kernel-gradient correction "
       << (spec.options.kernelGradientCorrection ? "on" : "off") << "; masses rho0 times "
       << (spec.tributaryVolumes ? "the tributary area (faces half, corners a quarter)" : "dx^2") << "; leapfrog at "
       << spec.options.courant << " h / (c_p (1 + 1.2 alpha)) and the force criterion, every step)";
  result.notes.push_back(what.str());
  std::ostringstream amplitude;
  amplitude << settings.name << ": small amplitude: the traction is " << eps
            << " times the scene's and the probes are divided by it, so the large-deformation method answers the "
               "linear problem";
  result.notes.push_back(amplitude.str());
  std::ostringstream force;
  force << std::setprecision(6) << settings.name << ": the strip's traction acts on " << strip.particles.size()
        << " particles of the loaded face with a total length " << strip.totalLength()
        << " (the strip's width " << 2 * load.halfWidth[static_cast<std::size_t>(1 - faceAxis(load.face))]
        << "; the end particles carry the half of their segment inside it)";
  result.notes.push_back(force.str());
  const FirstReflection reflection = firstReflection(scene, physical, probes, allFaces(D) & ~faceBit(load.face));
  result.notes.push_back(
      reflectionNote(settings.name,
                     "the updated-Lagrangian SPH leaves every face free (no dashpot), where the scene's [[boundary]] "
                     "asks otherwise (transmitting faces included)",
                     reflection, study.errorWindow) +
      "; the free body drifts with the load's net impulse once the waves reach its faces");

  RunStatistics stats;
  try {
    stats = loop.run(*integrator, scene.integrator.endTime);
  } catch (const InstabilityError& e) {
    recorder.writeCsv(folder + "/" + settings.name + "-probes.csv", std::vector<std::vector<Real>>(probes.size()));
    if (e.particle() < 0 || e.particle() >= record.particles) throw;
    std::ostringstream where;
    where << e.what() << " [updated-Lagrangian SPH: particle " << e.particle() << " starts at "
          << scene::formatPoint(std::vector<Real>{physical.position(e.particle())[0],
                                                  physical.position(e.particle())[1]})
          << "]";
    throw InstabilityError(where.str(), e.step(), e.time(), e.particle());
  }
  result.recordLoop(stats);
  record.timeStep = stats.steps > 0 ? (stats.endTime - stats.startTime) / static_cast<Real>(stats.steps) : 0;
  result.meanNeighbours = system.meanNeighbourCount();
  noteAllowedGrowth(result.notes, settings.name, {monitor.growthMessage()});

  scoreLambProbes<D>(study, settings, physical, recorder, nullptr, folder, result);
  record.peakMemoryMiB = peakMemoryMiB();
  return result;
}

}  // namespace mfwave::lamb3d
