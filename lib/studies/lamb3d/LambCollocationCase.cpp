#include "studies/lamb3d/LambCollocationCase.hpp"

#include "numerics/StableTimeStep.hpp"
#include "core/Error.hpp"
#include "core/Stopwatch.hpp"
#include "integrators/ConstrainedIntegrators.hpp"
#include "io/run/ProgressReporter.hpp"
#include "io/scene/BuildParticles.hpp"
#include "io/scene/Format.hpp"
#include "io/scene/StepLimitCheck.hpp"
#include "methods/collocation/CollocationSampler.hpp"
#include "methods/collocation/CollocationSystem.hpp"
#include "methods/collocation/ConstrainedCollocationSystem.hpp"
#include "observers/ReportedProbes.hpp"
#include "observers/StabilityMonitor.hpp"
#include "observers/TimeLoop.hpp"
#include "particles/BoxFace.hpp"
#include "studies/lamb3d/LambProbeScores.hpp"
#include "studies/lamb3d/LambReflection.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <memory>
#include <sstream>
#include <utility>
#include <vector>

namespace mfwave::lamb3d {

namespace {

// The probes of a collocation run: the interpolated field at each probe's node, u^h(x_p) = sum_J
// psi_J(x_p) d_J (Luo-Liu-Huang eq. (7)), or its rate with d', sampled without a solve
// (CollocationSampler). At an interior node u^h is the state itself (U = Psi_I d); on the loaded face
// it is what the traction rows make of the load. Raw and reported are the same value (collocation
// has nothing like the very weak SPH's deconvolution).
template <int D>
Eigen::MatrixXd probeFunctionals(const std::vector<Probe>& probes, const ShapeFunctions<D>& shapes,
                                 const ParticleSet<D>& particles, Index columns) {
  Eigen::MatrixXd rows = Eigen::MatrixXd::Zero(columns, static_cast<Index>(probes.size()));
  ShapeFunctionValues<D> values;
  for (std::size_t i = 0; i < probes.size(); ++i) {
    const Probe& p = probes[i];
    shapes.evaluate(particles.position(p.particle), 0, values);
    for (Index k = 0; k < values.size(); ++k)
      rows(values.nodes[static_cast<std::size_t>(k)] * D + p.component, static_cast<Index>(i)) =
          values.value[static_cast<std::size_t>(k)];
  }
  return rows;
}

template <int D>
class CollocationProbes : public ReportedProbes {
 public:
  CollocationProbes(std::vector<Probe> probes, const ShapeFunctions<D>& shapes, const ParticleSet<D>& particles,
                    const ConstrainedCollocationSystem& system)
      : ReportedProbes(std::move(probes)),
        sampler_(system, probeFunctionals<D>(this->probes(), shapes, particles, system.system().cols())) {
    for (const Probe& p : this->probes()) rate_.push_back(p.quantity == ProbeQuantity::Velocity);
  }

  void observe(const StateView& s) override {
    if (!beginSample(s.time)) return;
    const std::vector<Real> values = sampler_.sample(s.time, s.displacement, s.velocity, rate_);
    for (std::size_t i = 0; i < values.size(); ++i) add(i, values[i], values[i]);
  }

 private:
  CollocationSampler sampler_;
  std::vector<bool> rate_;
};

// The load's share at a node of the loaded face: w = 1 inside the patch, 1/2 on its edges, 1/4 at
// its corners (3-D), 0 outside; the edges fall on nodes and the product of the trapezoid rule's
// weights along each axis of the face gives the load's total force.
template <int D>
Real patchWeight(const LoadSpec& load, const Vec<D>& x, Real dx) {
  const int normalAxis = faceAxis(load.face);
  Real w = 1;
  for (int a = 0; a < D; ++a) {
    if (a == normalAxis) continue;
    const auto b = static_cast<std::size_t>(a);
    const Real distance = std::abs(x[a] - load.centre[b]), halfWidth = load.halfWidth[b];
    const Real edgeTolerance = 1e-9 * std::max(halfWidth, dx);
    w *= distance < halfWidth - edgeTolerance ? 1.0 : distance <= halfWidth + edgeTolerance ? 0.5 : 0.0;
  }
  return w;
}

template <int D>
CaseResult runCollocationCaseIn(const StudySettings& study, const CaseSettings& settings, const std::string& folder,
                                bool progress) {
  const Scene& scene = study.scene;
  const CollocationSpec& spec = *settings.collocation;
  CaseResult result;
  result.settings = settings;
  CaseRecord& record = result.record;
  record.name = settings.name;
  const Stopwatch setupClock;

  // nodes: the physical particles of the lattice (the very weak SPH case's, without its ghosts)
  const ParticleSet<D> particles = buildParticles<D>(settings.geometry);
  const Index nodeCount = particles.physicalCount();
  record.particles = nodeCount;
  Coordinates<D> nodes;
  for (int a = 0; a < D; ++a)
    nodes[static_cast<std::size_t>(a)].assign(particles.coordinates()[static_cast<std::size_t>(a)].begin(),
                                              particles.coordinates()[static_cast<std::size_t>(a)].begin() + nodeCount);
  const Real dx = settings.geometry.spacing;
  const std::unique_ptr<ShapeFunctions<D>> shapes = makeCollocationShapes<D>(spec, nodes, dx);

  // rows: interior nodes collocate the equation of motion; the loaded face (its corners in 2-D, its
  // edges and corners in 3-D excepted: nodes on another face too) the traction, every other
  // boundary node u = 0
  const LoadSpec& load = scene.loads[0];
  const Vec<D> normal = faceNormal<D>(load.face);
  CollocationPoints<D> points;
  Index tractionRows = 0;
  for (Index i = 0; i < nodeCount; ++i) {
    const std::uint8_t mask = particles.faceMask[static_cast<std::size_t>(i)];
    const Vec<D> x = particles.position(i);
    if (mask == 0) {
      points.add(x, CollocationRowKind::Interior);
    } else if (mask == faceBit(load.face)) {
      points.add(x, CollocationRowKind::Traction, normal);
      ++tractionRows;
    } else {
      points.add(x, CollocationRowKind::Displacement);
    }
  }
  // h(x, t) = traction w(x) f(t) (patchWeight).
  CollocationLoads<D> loads;
  Vec<D> traction;
  for (int a = 0; a < D; ++a) traction[a] = load.traction[static_cast<std::size_t>(a)];
  const TimeFunction history = load.timeFunction;
  loads.traction = [traction, load, dx, history](const Vec<D>& x, const Vec<D>&, Real t) {
    return Vec<D>(traction * (patchWeight<D>(load, x, dx) * history(t)));
  };
  const Material material = scene.material.material();
  ConstrainedCollocationSystem system(assembleCollocation<D>(*shapes, points, material, loads));
  result.operatorNonZeros = system.system().A.nonZeros();
  {
    ShapeFunctionValues<D> values;
    Real total = 0;
    for (std::size_t p = 0; p < points.size(); ++p) {
      shapes->evaluate(points.points[p], 0, values);
      total += static_cast<Real>(values.size());
    }
    result.meanNeighbours = total / static_cast<Real>(points.size());
  }

  // The step against the integrator's own limit on this operator (exit 2 above it, before stepping).
  const AccelerationSpectralRadius radius = accelerationSpectralRadius(system);
  const Real omegaMax = std::sqrt(radius.value);
  const Real criticalDt = 2 / omegaMax;
  if (!radius.converged) {
    // The largest eigenvalues of K come in close clusters, so the ratio creeps up to omega_max^2
    // from below (at dx = 0.25: 0.08 % under the dense eigenvalue after 400 iterations).
    std::ostringstream note;
    note << std::setprecision(2) << settings.name << ": the power iteration for omega_max^2 was still rising by "
         << radius.lastChange << " per iteration after " << radius.iterations
         << " (clustered largest eigenvalues); its last ratio, a little under omega_max^2, sets the step";
    result.notes.push_back(note.str());
  }
  const Real dt = scene.integrator.timeStepFor(criticalDt);
  record.stableTimeStep = criticalDt;
  record.timeStep = dt;
  record.simulatedTime = scene.integrator.endTime;
  const StepLimitCheck check = checkStepLimit(scene.integrator, scene.stability, omegaMax, dt, criticalDt,
                                              "a power iteration on the assembled collocation operator",
                                              "in case " + settings.name);
  if (!check.note.empty()) result.notes.push_back(check.note);

  const std::unique_ptr<SecondOrderIntegrator> integrator =
      makeConstrainedIntegrator(scene.integrator.name, scene.integrator.options);
  integrator->initialise(system, 0, Vector::Zero(system.size()), Vector::Zero(system.size()), dt);

  const std::vector<Probe> probes = resolveProbes(scene.probes, particles);
  CollocationProbes<D> recorder(probes, *shapes, particles, system);
  record.setupSeconds = setupClock.seconds();

  // What the case leaves out, and where its fixed faces start to matter.
  const unsigned fixedFaces = allFaces(D) & ~faceBit(load.face);
  const FirstReflection reflection = firstReflection<D>(scene, settings.geometry, particles, probes, fixedFaces);
  result.notes.push_back(reflectionNote(settings.name,
                                       "RK collocation fixes (u = 0) every face but the loaded one, where the scene's "
                                       "[[boundary]] asks otherwise (transmitting faces included)",
                                       reflection, study.errorWindow));
  result.notes.push_back(settings.name + ": " + std::to_string(tractionRows) + " traction rows on the loaded face, " +
                         std::to_string(system.boundaryRows().size() / D - static_cast<std::size_t>(tractionRows)) +
                         " displacement rows; no energy ledger and no frames for RK collocation");
  // The growth measured on the shipped scenes (LambCollocationCase.hpp): slow in 2-D, fast in 3-D.
  result.notes.push_back(settings.name +
                         ": the traction rows are not symmetric, and some pairs of the operator's modes are complex "
                         "and grow " +
                         (D == 2 ? std::string("slowly (on data/scenes/lamb2d.toml e-folding in about 75 s, at every "
                                               "spacing measured")
                                 : std::string("(on data/scenes/lamb3d.toml at dx = 0.5 e-folding in about 1.7 s, "
                                               "seeded at about 1e-5 of the response, so the error window does not "
                                               "see them; a run to t = 300 is stopped at t = 34.6")) +
                         ": lib/studies/lamb3d/LambCollocationCase.hpp); runs far beyond the error window grow until "
                         "the stability monitor stops them");

  StabilityMonitor monitor(scene.stability.options(D, loadsQuietAfter(scene)));
  ProgressReporter reporter(scene.integrator.endTime, nodeCount, progress);
  TimeLoop loop;
  loop.add(monitor);
  loop.add(reporter);
  loop.add(recorder, scene.output.probeEvery);
  RunStatistics stats;
  try {
    stats = loop.run(*integrator, scene.integrator.endTime);
  } catch (const InstabilityError& e) {
    // The probes recorded up to the stop stay readable (without the exact columns); the monitor's
    // "particle" is the interior unknown's point, which is said as the node it is.
    recorder.writeCsv(folder + "/" + settings.name + "-probes.csv", std::vector<std::vector<Real>>(probes.size()));
    if (e.particle() < 0 || D * e.particle() >= system.size()) throw;
    const Index node = system.interiorRows()[static_cast<std::size_t>(D * e.particle())] / D;
    std::ostringstream where;
    where << e.what() << " [RK collocation: interior point " << e.particle() << " is node " << node << " at "
          << formatPoint<D>(particles.position(node)) << "]";
    throw InstabilityError(where.str(), e.step(), e.time(), static_cast<long>(node));
  }
  result.recordLoop(stats);
  noteAllowedGrowth(result.notes, settings.name, {monitor.growthMessage()});

  scoreLambProbes<D>(study, settings, particles, recorder, nullptr, folder, result);
  record.peakMemoryMiB = peakMemoryMiB();
  return result;
}

}  // namespace

CaseResult runCollocationCase(const StudySettings& study, const CaseSettings& settings, const std::string& folder,
                              bool progress) {
  if (study.scene.loads.size() != 1 || study.scene.loads[0].type != LoadType::SurfacePatch)
    throw InputError("load", "the RK collocation case needs exactly one surface_patch load");
  if (study.scene.info.dimension == 2) return runCollocationCaseIn<2>(study, settings, folder, progress);
  if (study.scene.info.dimension == 3) return runCollocationCaseIn<3>(study, settings, folder, progress);
  throw InputError("method.name", "RK collocation runs the 2-D and 3-D Lamb problems (lamb2d, lamb3d)");
}

}  // namespace mfwave::lamb3d
