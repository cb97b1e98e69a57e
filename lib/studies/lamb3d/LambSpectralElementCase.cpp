#include "studies/lamb3d/LambSpectralElementCase.hpp"

#include "core/Error.hpp"
#include "core/Stopwatch.hpp"
#include "integrators/IntegratorFactory.hpp"
#include "io/run/ProgressReporter.hpp"
#include "io/run/RunSummary.hpp"
#include "io/scene/Format.hpp"
#include "methods/spectral_element/SpectralElementElasticity.hpp"
#include "observers/LinearEnergyLedger.hpp"
#include "observers/ReportedProbes.hpp"
#include "observers/StabilityMonitor.hpp"
#include "observers/TimeLoop.hpp"
#include "particles/BoxFace.hpp"
#include "studies/lamb3d/LambCaseLoop.hpp"
#include "studies/lamb3d/LambProbeScores.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <memory>
#include <sstream>
#include <utility>
#include <vector>

namespace mfwave::lamb3d {

namespace {

// The scene's faces for the SEM: transmitting -> dashpots, fixed -> u = 0, free -> natural.
template <int D>
std::array<SpectralElementFace, 2 * D> spectralElementFaces(const Scene& scene) {
  std::array<SpectralElementFace, 2 * D> faces = SpectralElementSettings<D>::uniformFaces(SpectralElementFace::Free);
  for (std::size_t i = 0; i < scene.boundaries.size(); ++i) {
    const BoundarySpec& b = scene.boundaries[i];
    SpectralElementFace kind = SpectralElementFace::Free;
    switch (b.type) {
      case BoundaryType::Free: kind = SpectralElementFace::Free; break;
      case BoundaryType::Fixed: kind = SpectralElementFace::Fixed; break;
      case BoundaryType::Transmitting: kind = SpectralElementFace::Absorbing; break;
      default:
        throw InputError("boundary[" + std::to_string(i) + "].type",
                         "the spectral-element case runs free, fixed and transmitting faces, not " +
                             boundaryTypeName(b.type));
    }
    for (int face = 0; face < 2 * D; ++face)
      if ((b.faceMask & faceBit(face)) != 0) faces[static_cast<std::size_t>(face)] = kind;
  }
  return faces;
}

template <int D>
SpectralElementSettings<D> spectralElementSettings(const Scene& scene, const CaseSettings& settings) {
  const LoadSpec& load = scene.loads[0];
  const int order = *settings.spectralElementOrder;
  SpectralElementSettings<D> s;
  const GeometrySpec& g = settings.geometry;
  SpectralElementTraction<D> traction;
  traction.face = load.face;
  for (int d = 0; d < D; ++d) {
    const auto k = static_cast<std::size_t>(d);
    s.lower[d] = g.lower[k];
    s.upper[d] = g.upper[k];
    traction.centre[d] = load.centre[k];
    traction.halfWidth[d] = load.halfWidth[k];
    traction.traction[d] = load.traction[k];
  }
  s.order = order;
  s.elementSize = order * g.spacing;
  s.material = scene.material.material();
  s.faces = spectralElementFaces<D>(scene);
  const TimeFunction history = load.timeFunction;
  traction.history = [history](Real t) { return history(t); };
  s.tractions.push_back(std::move(traction));
  return s;
}

template <int D>
CaseResult runSpectralElementCaseIn(const StudySettings& study, const CaseSettings& settings, const std::string& folder,
                                    bool progress) {
  const Scene& scene = study.scene;
  if (scene.loads.size() != 1 || scene.loads[0].type != LoadType::SurfacePatch)
    throw InputError("load", "the spectral-element case needs exactly one surface_patch load");
  if (!settings.spectralElementOrder) throw InputError("method.order", "the spectral-element case needs its order");
  CaseResult result;
  result.settings = settings;
  CaseRecord& record = result.record;
  record.name = settings.name;
  const Stopwatch setupClock;

  const int order = *settings.spectralElementOrder;
  const Real elementSize = order * settings.geometry.spacing;
  std::unique_ptr<SpectralElementElasticity<D>> built;
  try {
    built = std::make_unique<SpectralElementElasticity<D>>(spectralElementSettings<D>(scene, settings));
  } catch (const InputError& e) {
    std::ostringstream problem;
    if (e.key() == "elementSize") {
      problem << "the spectral elements of order " << order << " are " << order << " spacings wide ("
              << elementSize << "): " << e.problem();
      throw InputError("geometry.spacing", problem.str());
    }
    if (e.key() == "traction") throw InputError("load.half_width", e.problem());
    throw;
  }
  SpectralElementElasticity<D>& system = *built;
  const ParticleSet<D> particles = system.nodeParticles();
  record.particles = system.nodeCount();
  result.meanNeighbours = 0;
  // all that is stored of K: the one dense element matrix in 2-D, the (N + 1)^2 derivative matrix
  // of the sum-factorised product in 3-D
  const Index elementDofs = D * (D == 2 ? (order + 1) * (order + 1) : (order + 1) * (order + 1) * (order + 1));
  result.operatorNonZeros = D == 2 ? elementDofs * elementDofs : static_cast<Index>((order + 1) * (order + 1));

  // time step: a fraction of the operator's stable central-difference step (exit 2 above the limit)
  const Real dt = chooseLambTimeStep(system, scene, "M^-1 K of the spectral elements", result);

  // the energy ledger, which also stops growth after the loads (as in the very weak SPH case)
  const LinearEnergyLedgerOptions ledgerOptions = lambLedgerOptions(
      scene, settings.geometry, D, scene.material.material(), false,
      "the spectral-element operator is symmetric with a diagonal mass: growth means a step above the limit");
  LinearEnergyLedger ledger(system, ledgerOptions);

  const std::unique_ptr<SecondOrderIntegrator> integrator =
      makeSecondOrderIntegrator(scene.integrator.name, scene.integrator.options);
  integrator->initialise(system, 0, Vector::Zero(system.size()), Vector::Zero(system.size()), dt);

  const std::vector<Probe> probes = resolveProbes(scene.probes, particles);
  for (std::size_t i = 0; i < probes.size(); ++i) {
    if (!scene.probes[i].position) continue;
    Vec<D> wanted;
    for (int d = 0; d < D; ++d) wanted[d] = (*scene.probes[i].position)[static_cast<std::size_t>(d)];
    const Real offset = (particles.position(probes[i].particle) - wanted).norm();
    if (offset > 1e-9 * elementSize) {
      std::ostringstream note;
      note << std::setprecision(3) << settings.name << ": probe " << probes[i].name << " reads the GLL node "
           << offset << " from its position (" << scene::formatPoint<D>(particles.position(probes[i].particle)) << ")";
      result.notes.push_back(note.str());
    }
  }
  NodalProbes recorder(probes, D);  // the SEM field at a GLL node is its nodal value
  record.setupSeconds = setupClock.seconds();
  {
    std::ostringstream note;
    note << settings.name << ": spectral elements of order " << order << ", ";
    for (int d = 0; d < D; ++d) note << (d > 0 ? " x " : "") << system.elementsPerAxis()[static_cast<std::size_t>(d)];
    note << " elements of side " << elementSize << ", " << system.nodeCount()
         << " GLL nodes; the scene's transmitting faces are Lysmer-Kuhlemeyer dashpots on the nodes";
    result.notes.push_back(note.str());
  }

  StabilityMonitor monitor(scene.stability.options(D, ledgerOptions.quietAfter));
  ProgressReporter reporter(scene.integrator.endTime, system.nodeCount(), progress);
  TimeLoop loop;
  loop.add(monitor);
  loop.add(ledger);
  loop.add(reporter);
  loop.add(recorder, scene.output.probeEvery);
  runLambLoopWithLedger(loop, *integrator, scene, recorder, ledger, monitor, folder, result);

  scoreLambProbes<D>(study, settings, particles, recorder, nullptr, folder, result);
  record.peakMemoryMiB = peakMemoryMiB();
  return result;
}

}  // namespace

CaseResult runSpectralElementCase(const StudySettings& study, const CaseSettings& settings, const std::string& folder,
                                  bool progress) {
  if (study.scene.info.dimension == 2) return runSpectralElementCaseIn<2>(study, settings, folder, progress);
  if (study.scene.info.dimension == 3) return runSpectralElementCaseIn<3>(study, settings, folder, progress);
  throw InputError("scene.dimension", "the spectral-element case runs 2-D and 3-D scenes");
}

}  // namespace mfwave::lamb3d
