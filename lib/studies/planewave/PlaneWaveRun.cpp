#include "PlaneWaveRun.hpp"

#include "numerics/DispersionSpectrum.hpp"
#include "numerics/StableTimeStep.hpp"
#include "analytic/PlaneWave.hpp"
#include "core/Error.hpp"
#include "core/Stopwatch.hpp"
#include "integrators/IntegratorFactory.hpp"
#include "integrators/StabilityLimit.hpp"
#include "integrators/TimeStep.hpp"
#include "io/scene/IntegratorSpec.hpp"
#include "observers/TimeLoop.hpp"
#include "methods/spectral_element/SpectralElementElasticity.hpp"
#include "systems/LinearSecondOrderSystem.hpp"

#include <cmath>
#include <memory>
#include <sstream>

namespace mfwave::planewave {
namespace {

// The step a fraction s.cfl of the central-difference limit 2 / omegaMax, refused (exit 2) beyond
// the integrator's own limit L / omega_max (integrators/StabilityLimit): the limit is known, so
// round-off would otherwise seed growing modes while a short run could still look accurate.
void checkIntegratorLimit(const Settings& s, Real omegaMax, Real stableStep) {
  const StepVerdict verdict = judgeStep(s.integrator, {}, omegaMax, s.cfl * stableStep);
  if (verdict.aboveLimit)
    throw InputError("integrator.cfl", std::to_string(s.cfl) + " is beyond the " + verdict.limit.integrator +
                                           " limit " + std::to_string(verdict.limit.omegaDtLimit) +
                                           " / omega_max = " + std::to_string(verdict.limitDt) +
                                           " of this spectrum (cfl <= " +
                                           std::to_string(verdict.limitDt / stableStep) + ")");
}

// The exact wave of `s`: k along the direction with s.wavelengths across the unit box, e along k
// (P) or normal to it (S).
template <int D>
PlaneWave<D> exactWave(const Settings& s) {
  const Vec<D> n = latticeDirectionVector<D>(s.direction);
  const Vec<D> k = (s.direction == LatticeDirection::Axis ? 1.0 : std::sqrt(Real(D))) * 2 * kPi * s.wavelengths * n;
  Vec<D> e = n;
  if (s.shear) {
    e.setZero();
    if constexpr (D == 2) e << -n(1), n(0);
    if constexpr (D == 3) {
      if (s.direction == LatticeDirection::Axis) e(1) = 1;
      else e << 1 / std::sqrt(2.0), -1 / std::sqrt(2.0), 0;
    }
  }
  const Real speed = s.shear ? s.lattice.material.sWaveSpeed() : s.lattice.material.pWaveSpeed();
  return PlaneWave<D>(k, e, speed);
}

// Fills the record's end time, steps and dt: s.periods of the wave at s.cfl of `stableStep`,
// shortened to land on the end (chooseTimeStep, the step's one home).
template <int D>
void planSteps(const Settings& s, const PlaneWave<D>& wave, CaseRecord& record) {
  record.simulatedTime = s.periods * wave.period();
  TimeStepRule rule;
  rule.endTime = record.simulatedTime;
  rule.cfl = s.cfl;
  try {
    const TimeStepChoice choice = chooseTimeStep(rule, record.stableTimeStep);
    record.steps = choice.steps;
    record.timeStep = choice.dt;
  } catch (const InputError& e) {
    std::ostringstream what;
    what << s.periods << " periods at cfl " << s.cfl << ": " << e.what();
    throw InputError("study.periods", what.str());
  }
}

// Stops a growing field at once: anything non-finite or a thousand times the initial amplitude
// (the exact wave keeps its amplitude) is a blow-up. It looks at the state only, so a restored run
// needs nothing from it.
class GrowthWatch : public StatelessObserver {
 public:
  GrowthWatch(const Vector& u0, int components)
      : initial_(u0.cwiseAbs().maxCoeff()), limit_(1e3 * std::max<Real>(initial_, 1e-300)), components_(components) {}
  void observe(const StateView& state) override {
    Index worst = 0;
    const Real largest = state.displacement.cwiseAbs().maxCoeff(&worst);
    if (!std::isfinite(largest) || largest > limit_)
      throw InstabilityError("planewave: the field grew to " + std::to_string(largest) + " (initial amplitude " +
                                 std::to_string(initial_) + ") by step " + std::to_string(state.step) + ", t = " +
                                 std::to_string(state.time) + ", at node " + std::to_string(worst / components_) +
                                 ": the step is beyond the integrator's limit",
                             state.step, state.time, static_cast<long>(worst / components_));
  }

 private:
  Real initial_, limit_;
  int components_;
};

// Steps `integrator` (initialised) through record.steps in a TimeLoop (interruptible, and
// checkpointed when the run asks), watching for growth every 16 steps and at the last, and returns
// its displacement.
Vector stepWatchingGrowth(SecondOrderIntegrator& integrator, const Vector& u0, int components, CaseRecord& record) {
  GrowthWatch watch(u0, components);
  TimeLoop loop;
  loop.add(watch, 16);
  const RunStatistics stats = loop.run(integrator, record.simulatedTime);
  record.loopSeconds = stats.wallSeconds;
  record.steps = stats.steps;
  if (stats.interrupted) record.simulatedTime = record.interruptedAt = stats.endTime;  // errors of the part that ran
  record.resumedFromStep = stats.resumedFromStep;
  return integrator.state().displacement;
}

void recordError(const Settings& s, Real error, Outcome& out) {
  out.error = error;
  out.record.name = s.method + " " + std::to_string(s.dimension) + "-D, " + std::to_string(s.cells) + " cells, " +
                    s.integrator;
  out.record.errors = {{"relative_l2_u", error}};
  out.record.primaryError = "relative_l2_u";
}

template <int D>
Outcome runLattice(const Settings& s) {
  Stopwatch clock;
  const Real dx = 1.0 / s.cells;
  const MethodLatticeStencil<D> stencil = latticeMethodStencil<D>(s.method, s.lattice, dx, "study.method");
  const auto op = makePeriodicLatticeOperator<D>(stencil.acceleration, dx, s.cells, stencil.mass);
  const int c = op.components();
  if (c == 1 && s.shear) throw InputError("study.polarisation", "the scalar finite difference has no S wave");

  const auto extremes = DispersionSpectrum<D>(op).extremes();
  // omega^2 < 0 anywhere on the lattice grows at any step: stop before any work, as an instability
  // (exit 3), naming where in k it sits.
  if (!(extremes.smallestOmegaSquared >= -1e-10 * extremes.largestOmegaSquared)) {
    std::ostringstream where;
    where << (extremes.smallestAt * dx).transpose();
    throw InstabilityError("planewave: study.method " + s.method + ": the discrete spectrum has omega^2 < 0 (" +
                               std::to_string(extremes.smallestOmegaSquared / extremes.largestOmegaSquared) +
                               " of its largest value, at k dx = (" + where.str() +
                               ")): unstable at any step; see docs/studies/spectra.md",
                           0, 0, -1);
  }
  Outcome out;
  CaseRecord& record = out.record;
  record.stableTimeStep = 2 / std::sqrt(extremes.largestOmegaSquared);
  checkIntegratorLimit(s, std::sqrt(extremes.largestOmegaSquared), record.stableTimeStep);
  const PlaneWave<D> wave = exactWave<D>(s);
  planSteps<D>(s, wave, record);

  // Nodal values of the exact field; collocation unknowns are coefficients d with M d = u.
  const Index nodes = op.nodes();
  record.particles = nodes;
  const Vec<D> e = wave.displacement(Vec<D>::Zero(), 0).normalized();
  auto nodal = [&](Real t, bool velocity) {
    Vector values(op.size());
    for (Index node = 0; node < nodes; ++node) {
      const std::array<int, D> at = latticeCoordinates<D>(node, s.cells);
      Vec<D> x;
      for (int d = 0; d < D; ++d) x(d) = at[static_cast<std::size_t>(d)] * dx;
      const Vec<D> u = velocity ? wave.velocity(x, t) : wave.displacement(x, t);
      if (c == 1)
        values(node) = u.dot(e);
      else
        values.segment<D>(node * D) = u;
    }
    return values;
  };
  // A lumped method under an explicit integrator steps matrix-free (the stencil applied by lattice
  // arithmetic, lib/lattice/PeriodicStencilSystem); a consistent mass and Newmark need the matrices.
  const bool matrixFree = op.lumped() && namedIntegrator(s.integrator).name != "newmark";
  std::unique_ptr<LinearOperatorSystem> stencilSystem;
  std::unique_ptr<LinearSecondOrderSystem> matrixSystem;
  if (matrixFree)
    stencilSystem = periodicStencilSystem(op);
  else
    matrixSystem = std::make_unique<LinearSecondOrderSystem>(periodicLatticeSystem(op));
  LinearOperatorSystem& system = matrixFree ? *stencilSystem : static_cast<LinearOperatorSystem&>(*matrixSystem);
  Vector u0 = nodal(0, false), v0 = nodal(0, true);
  if (!op.lumped()) {
    // The factorisation the explicit integrators then solve with every step.
    u0 = matrixSystem->solveMass(u0);
    v0 = matrixSystem->solveMass(v0);
  }
  auto integrator = makeSecondOrderIntegrator(s.integrator);
  integrator->initialise(system, 0, u0, v0, record.timeStep);
  record.setupSeconds = clock.seconds();
  const Vector d = stepWatchingGrowth(*integrator, u0, c, record);
  const Vector u = op.lumped() ? Vector(d) : Vector(matrixSystem->mass() * d);
  const Vector exact = nodal(record.simulatedTime, false);
  recordError(s, (u - exact).norm() / exact.norm(), out);
  return out;
}

// The spectral-element reference (SpectralElementElasticity with periodic faces): GLL order
// s.semOrder on square / cubic elements s.semOrder spacings wide, so the node count and mean
// spacing are the lattice's. Its nodes are not equally spaced, so the error is the GLL quadrature's
// L2 norm (the lumped mass as weights) instead of the plain nodal one; the step a fraction of
// 2 / omega_max from a power iteration on M^-1 K (symmetric positive semi-definite by construction,
// so no spectrum check).
template <int D>
Outcome runSpectralElement(const Settings& s) {
  Stopwatch clock;
  if (s.cells % s.semOrder != 0 || (s.cells / s.semOrder > 1 && (s.cells / s.semOrder) % 2 != 0))
    throw InputError("study.cells", std::to_string(s.cells) + " cells are not an even number (or one) of elements of order " +
                                        std::to_string(s.semOrder) + " (" + std::to_string(s.semOrder) +
                                        " spacings wide): choose cells a multiple of 2 x study.sem_order");
  if (namedIntegrator(s.integrator).name == "newmark")
    throw InputError("integrator.name", "the spectral elements are matrix-free: central_difference, leapfrog or arkode");
  SpectralElementSettings<D> mesh;
  mesh.lower = Vec<D>::Zero();
  mesh.upper = Vec<D>::Ones();
  mesh.order = s.semOrder;
  mesh.elementSize = static_cast<Real>(s.semOrder) / s.cells;
  mesh.material = s.lattice.material;
  mesh.faces = SpectralElementSettings<D>::uniformFaces(SpectralElementFace::Periodic);
  SpectralElementElasticity<D> system(mesh);

  Outcome out;
  CaseRecord& record = out.record;
  // omega_max from a periodic block of at most 4 elements per axis, the same elements: a periodic
  // mesh's spectrum is the union of its elements' Bloch spectra at the wavenumbers it holds, and the
  // largest Bloch frequency sits at k = 0 or pi / h (held by 4 elements). Measured at N = 4: the
  // block's step times (elements / 4) equals the whole mesh's power iteration to 4e-5 at 128 cells,
  // in 180 iterations on 4^2 elements instead of 777 on 32^2.
  SpectralElementSettings<D> block = mesh;
  block.upper = Vec<D>::Constant(std::min<Real>(static_cast<Real>(s.cells / s.semOrder), 4) * mesh.elementSize);
  const StableTimeStep stable = centralDifferenceStableStep(SpectralElementElasticity<D>(block), 1e-6, 5000);
  record.stableTimeStep = stable.usable();
  checkIntegratorLimit(s, 2 / record.stableTimeStep, record.stableTimeStep);
  const PlaneWave<D> wave = exactWave<D>(s);
  planSteps<D>(s, wave, record);
  record.particles = system.nodeCount();
  auto nodal = [&](Real t, bool velocity) {
    Vector values(system.size());
    for (Index node = 0; node < system.nodeCount(); ++node) {
      const Vec<D> x = system.nodePosition(node);
      values.segment<D>(node * D) = velocity ? wave.velocity(x, t) : wave.displacement(x, t);
    }
    return values;
  };
  const Vector u0 = nodal(0, false);
  auto integrator = makeSecondOrderIntegrator(s.integrator);
  integrator->initialise(system, 0, u0, nodal(0, true), record.timeStep);
  record.setupSeconds = clock.seconds();
  const Vector u = stepWatchingGrowth(*integrator, u0, D, record);
  const Vector exact = nodal(record.simulatedTime, false);
  const Vector& weights = system.lumpedMass();
  recordError(s, std::sqrt((u - exact).cwiseAbs2().dot(weights) / exact.cwiseAbs2().dot(weights)), out);
  return out;
}

template <int D>
Outcome run(const Settings& s) {
  if (D == 1 && s.shear) throw InputError("study.polarisation", "there is no S wave in 1-D");
  if (s.method == "spectral_element") {
    if constexpr (D == 1)
      throw InputError("study.method", "the spectral elements run in 2-D and 3-D");
    else
      return runSpectralElement<D>(s);
  }
  return runLattice<D>(s);
}

}  // namespace

Outcome runPlaneWave(const Settings& s) {
  if (s.dimension == 1) return run<1>(s);
  if (s.dimension == 2) return run<2>(s);
  return run<3>(s);
}

}  // namespace mfwave::planewave
