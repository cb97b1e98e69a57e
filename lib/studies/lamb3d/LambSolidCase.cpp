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
#include "wiring/SolidIntegration.hpp"
#include "wiring/SolidStateAdapter.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <memory>
#include <sstream>
#include <utility>

namespace mfwave::lamb3d {

namespace {

// What the patch is, in the words of the case's notes: a strip (2-D) or a rectangle (3-D).
template <int D>
std::string patchNote(const std::string& caseName, const LoadSpec& load, const PatchTraction& patch) {
  Real measure = 1;
  for (int d = 0; d < D; ++d)
    if (d != faceAxis(load.face)) measure *= 2 * load.halfWidth[static_cast<std::size_t>(d)];
  std::ostringstream note;
  note << std::setprecision(6) << caseName << ": the " << (D == 2 ? "strip" : "square") << "'s traction acts on "
       << patch.particles.size() << " particles of the loaded face with a total " << (D == 2 ? "length " : "area ")
       << patch.totalMeasure() << " (the " << (D == 2 ? "strip's width " : "patch's area ") << measure
       << (D == 2 ? "; the end particles carry the half of their segment inside it)"
                  : "; the particles on its edges carry the part of their tributary square inside it)");
  return note.str();
}

template <int D>
CaseResult runSolidCaseIn(const StudySettings& study, const CaseSettings& settings, const std::string& folder,
                          bool progress) {
  const Scene& scene = study.scene;
  if (scene.loads.size() != 1 || scene.loads[0].type != LoadType::SurfacePatch)
    throw InputError("load", "the updated-Lagrangian SPH case needs exactly one surface_patch load");
  const LambSolidSpec& spec = *settings.solid;
  const Real eps = spec.amplitude;
  CaseResult result;
  result.settings = settings;
  CaseRecord& record = result.record;
  record.name = settings.name;
  const Stopwatch setupClock;

  const ParticleSet<D> physical = lambSolidParticles<D>(settings.geometry, spec.tributaryVolumes);
  record.particles = physical.physicalCount();
  UpdatedLagrangianSph<D> system(physical, lambSolidOptions<D>(spec, physical, settings.geometry.spacing));
  result.smoothingLength = system.smoothingLength();
  const LoadSpec& load = scene.loads[0];
  const PatchTraction patch = patchTraction<D>(load, physical, settings.geometry.spacing);
  applyPatchLoad<D>(system, load, patch, eps);
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
  NodalProbes recorder(probes, D, eps);  // u = x - X and v over eps
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
       << (!spec.tributaryVolumes ? (D == 2 ? "dx^2" : "dx^3")
           : D == 2              ? "the tributary area (faces half, corners a quarter)"
                                 : "the tributary volume (faces half, edges a quarter, corners an eighth)")
       << "; leapfrog at " << spec.options.courant << " h / (c_p (1 + 1.2 alpha)) and the force criterion, every step)";
  result.notes.push_back(what.str());
  std::ostringstream amplitude;
  amplitude << settings.name << ": small amplitude: the traction is " << eps
            << " times the scene's and the probes are divided by it, so the large-deformation method answers the "
               "linear problem";
  result.notes.push_back(amplitude.str());
  result.notes.push_back(patchNote<D>(settings.name, load, patch));
  const FirstReflection reflection =
      firstReflection<D>(scene, settings.geometry, physical, probes, allFaces(D) & ~faceBit(load.face));
  result.notes.push_back(
      reflectionNote(settings.name,
                     "the updated-Lagrangian SPH leaves every face of its box " + settings.geometry.describeBox() +
                         " free (no dashpot), where the scene's [[boundary]] asks otherwise (transmitting faces "
                         "included)",
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
          << scene::formatPoint<D>(physical.position(e.particle())) << "]";
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

}  // namespace

Real PatchTraction::totalMeasure() const {
  Real total = 0;
  for (Real m : measures) total += m;
  return total;
}

template <int D>
PatchTraction patchTraction(const LoadSpec& load, const ParticleSet<D>& particles, Real dx) {
  const int normal = faceAxis(load.face);
  // The face's extent: the lattice's first and last positions along each axis.
  Vec<D> faceLower = Vec<D>::Constant(std::numeric_limits<Real>::infinity());
  Vec<D> faceUpper = -faceLower;
  for (Index i = 0; i < particles.physicalCount(); ++i) {
    faceLower = faceLower.cwiseMin(particles.position(i));
    faceUpper = faceUpper.cwiseMax(particles.position(i));
  }
  PatchTraction patch;
  for (Index i = 0; i < particles.physicalCount(); ++i) {
    if ((particles.faceMask[static_cast<std::size_t>(i)] & faceBit(load.face)) == 0) continue;
    const Vec<D> x = particles.position(i);
    // The particle's tributary facet of the face, inside the patch: a product of clipped segments.
    Real measure = 1;
    for (int a = 0; a < D; ++a) {
      if (a == normal) continue;
      const auto k = static_cast<std::size_t>(a);
      const Real lower = std::max({x[a] - dx / 2, faceLower[a], load.centre[k] - load.halfWidth[k]});
      const Real upper = std::min({x[a] + dx / 2, faceUpper[a], load.centre[k] + load.halfWidth[k]});
      measure *= std::max<Real>(upper - lower, 0);
    }
    if (measure <= 1e-12 * std::pow(dx, D - 1)) continue;
    patch.particles.push_back(i);
    patch.measures.push_back(measure);
  }
  return patch;
}

template <int D>
ParticleSet<D> lambSolidParticles(const GeometrySpec& geometry, bool tributaryVolumes) {
  // the very weak SPH case's lattice without its ghosts, which the method refuses (its faces are free)
  GeometrySpec lattice = geometry;
  lattice.ghostLayers = 0;
  lattice.ghostFaces = 0;
  ParticleSet<D> particles = buildParticles<D>(lattice);
  if (tributaryVolumes)
    for (Index i = 0; i < particles.physicalCount(); ++i)
      particles.volume[static_cast<std::size_t>(i)] *= std::pow(0.5, particles.facetCount(i));
  return particles;
}

template <int D>
UpdatedLagrangianSphOptions lambSolidOptions(const LambSolidSpec& spec, const ParticleSet<D>& particles, Real dx) {
  // The method takes its spacing as the D-th root of the mean volume, which the tributary volumes of
  // the faces make smaller than dx: the ratio is rescaled so that h = ratio * dx.
  Real total = 0;
  for (Index i = 0; i < particles.physicalCount(); ++i) total += particles.volume[static_cast<std::size_t>(i)];
  const Real meanSpacing = std::pow(total / static_cast<Real>(particles.physicalCount()), Real(1) / D);
  UpdatedLagrangianSphOptions options = spec.options;
  options.smoothingLengthRatio = spec.options.smoothingLengthRatio * dx / meanSpacing;
  return options;
}

template <int D>
void applyPatchLoad(UpdatedLagrangianSph<D>& system, const LoadSpec& load, const PatchTraction& patch, Real amplitude) {
  Vec<D> traction;
  for (int d = 0; d < D; ++d) traction[d] = amplitude * load.traction[static_cast<std::size_t>(d)];
  for (std::size_t k = 0; k < patch.particles.size();) {
    // one traction group per run of equal measures (the inner particles share dx^(D-1))
    std::size_t end = k + 1;
    const Real measure = patch.measures[k];
    while (end < patch.particles.size() && std::abs(patch.measures[end] - measure) <= 1e-12 * measure) ++end;
    system.addTraction(std::vector<Index>(patch.particles.begin() + static_cast<std::ptrdiff_t>(k),
                                          patch.particles.begin() + static_cast<std::ptrdiff_t>(end)),
                       traction, load.timeFunction, patch.measures[k]);
    k = end;
  }
}

template PatchTraction patchTraction<2>(const LoadSpec&, const ParticleSet<2>&, Real);
template PatchTraction patchTraction<3>(const LoadSpec&, const ParticleSet<3>&, Real);
template ParticleSet<2> lambSolidParticles<2>(const GeometrySpec&, bool);
template ParticleSet<3> lambSolidParticles<3>(const GeometrySpec&, bool);
template UpdatedLagrangianSphOptions lambSolidOptions<2>(const LambSolidSpec&, const ParticleSet<2>&, Real);
template UpdatedLagrangianSphOptions lambSolidOptions<3>(const LambSolidSpec&, const ParticleSet<3>&, Real);
template void applyPatchLoad<2>(UpdatedLagrangianSph<2>&, const LoadSpec&, const PatchTraction&, Real);
template void applyPatchLoad<3>(UpdatedLagrangianSph<3>&, const LoadSpec&, const PatchTraction&, Real);

CaseResult runSolidCase(const StudySettings& study, const CaseSettings& settings, const std::string& folder,
                        bool progress) {
  if (study.scene.info.dimension == 2) return runSolidCaseIn<2>(study, settings, folder, progress);
  if (study.scene.info.dimension == 3) return runSolidCaseIn<3>(study, settings, folder, progress);
  throw InputError("method.name", "the updated-Lagrangian SPH runs the 2-D and 3-D Lamb problems (lamb2d, lamb3d)");
}

}  // namespace mfwave::lamb3d
