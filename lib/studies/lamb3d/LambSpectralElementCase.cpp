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

// The probes of a spectral-element run: the state at the probe's GLL node (the SEM field there is
// the nodal value; raw and reported are the same).
class SpectralElementProbes : public ReportedProbes {
 public:
  using ReportedProbes::ReportedProbes;

  void observe(const StateView& s) override {
    if (!beginSample(s.time)) return;
    for (std::size_t i = 0; i < probes().size(); ++i) {
      const Probe& p = probes()[i];
      const Vector& field = p.quantity == ProbeQuantity::Velocity ? s.velocity : s.displacement;
      const Real value = field[2 * p.particle + p.component];
      add(i, value, value);
    }
  }
};

// The scene's faces for the SEM: transmitting -> dashpots, fixed -> u = 0, free -> natural.
std::array<SpectralElementFace, 4> spectralElementFaces(const Scene& scene) {
  std::array<SpectralElementFace, 4> faces{SpectralElementFace::Free, SpectralElementFace::Free,
                                           SpectralElementFace::Free, SpectralElementFace::Free};
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
    for (int face = 0; face < 4; ++face)
      if ((b.faceMask & faceBit(face)) != 0) faces[static_cast<std::size_t>(face)] = kind;
  }
  return faces;
}

SpectralElementSettings spectralElementSettings(const Scene& scene, const CaseSettings& settings) {
  const LoadSpec& load = scene.loads[0];
  const int order = *settings.spectralElementOrder;
  SpectralElementSettings s;
  const GeometrySpec& g = settings.geometry;
  s.lower = Vec2(g.lower[0], g.lower[1]);
  s.upper = Vec2(g.upper[0], g.upper[1]);
  s.order = order;
  s.elementSize = order * g.spacing;
  s.material = scene.material.material();
  s.faces = spectralElementFaces(scene);
  const auto along = static_cast<std::size_t>(1 - faceAxis(load.face));
  SpectralElementTraction traction;
  traction.face = load.face;
  traction.centre = load.centre[along];
  traction.halfWidth = load.halfWidth[along];
  traction.traction = Vec2(load.traction[0], load.traction[1]);
  const TimeFunction history = load.timeFunction;
  traction.history = [history](Real t) { return history(t); };
  s.tractions.push_back(std::move(traction));
  return s;
}

}  // namespace

CaseResult runSpectralElementCase(const StudySettings& study, const CaseSettings& settings, const std::string& folder,
                                  bool progress) {
  const Scene& scene = study.scene;
  if (scene.info.dimension != 2)
    throw InputError("method.name", "the spectral-element case runs the 2-D Lamb problem (lamb2d) only");
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
  std::unique_ptr<SpectralElementElasticity> built;
  try {
    built = std::make_unique<SpectralElementElasticity>(spectralElementSettings(scene, settings));
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
  SpectralElementElasticity& system = *built;
  const ParticleSet<2> particles = system.nodeParticles();
  record.particles = system.nodeCount();
  result.meanNeighbours = 0;
  result.operatorNonZeros = system.elementStiffness().size();  // the one element matrix, all that is stored

  // time step: a fraction of the operator's stable central-difference step (exit 2 above the limit)
  const Real dt = chooseLambTimeStep(system, scene, "M^-1 K of the spectral elements", result);

  // the energy ledger, which also stops growth after the loads (as in the very weak SPH case)
  const LinearEnergyLedgerOptions ledgerOptions = lambLedgerOptions(
      scene, settings.geometry, 2, scene.material.material(), false,
      "the spectral-element operator is symmetric with a diagonal mass: growth means a step above the limit");
  LinearEnergyLedger ledger(system, ledgerOptions);

  const std::unique_ptr<SecondOrderIntegrator> integrator =
      makeSecondOrderIntegrator(scene.integrator.name, scene.integrator.options);
  integrator->initialise(system, 0, Vector::Zero(system.size()), Vector::Zero(system.size()), dt);

  const std::vector<Probe> probes = resolveProbes(scene.probes, particles);
  for (std::size_t i = 0; i < probes.size(); ++i) {
    if (!scene.probes[i].position) continue;
    const Vec2 wanted((*scene.probes[i].position)[0], (*scene.probes[i].position)[1]);
    const Real offset = (particles.position(probes[i].particle) - wanted).norm();
    if (offset > 1e-9 * elementSize) {
      std::ostringstream note;
      note << std::setprecision(3) << settings.name << ": probe " << probes[i].name << " reads the GLL node "
           << offset << " from its position (" << scene::formatPoint({particles.position(probes[i].particle)[0], particles.position(probes[i].particle)[1]}) << ")";
      result.notes.push_back(note.str());
    }
  }
  SpectralElementProbes recorder(probes);
  record.setupSeconds = setupClock.seconds();
  {
    std::ostringstream note;
    note << settings.name << ": spectral elements of order " << order << ", " << system.elementsPerAxis()[0] << " x "
         << system.elementsPerAxis()[1] << " elements of side " << elementSize << ", " << system.nodeCount()
         << " GLL nodes; the scene's transmitting faces are Lysmer-Kuhlemeyer dashpots on the nodes";
    result.notes.push_back(note.str());
  }

  StabilityMonitor monitor(scene.stability.options(2, ledgerOptions.quietAfter));
  ProgressReporter reporter(scene.integrator.endTime, system.nodeCount(), progress);
  TimeLoop loop;
  loop.add(monitor);
  loop.add(ledger);
  loop.add(reporter);
  loop.add(recorder, scene.output.probeEvery);
  runLambLoopWithLedger(loop, *integrator, scene, recorder, ledger, monitor, folder, result);

  scoreLambProbes<2>(study, settings, particles, recorder, nullptr, folder, result);
  record.peakMemoryMiB = peakMemoryMiB();
  return result;
}

}  // namespace mfwave::lamb3d
