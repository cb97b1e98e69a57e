#include "PlaneWaveRun.hpp"

#include "analysis/DispersionSpectrum.hpp"
#include "analytic/PlaneWave.hpp"
#include "core/Error.hpp"
#include "core/Stopwatch.hpp"
#include "integrators/IntegratorFactory.hpp"
#include "integrators/StabilityLimit.hpp"
#include "io/scene/IntegratorSpec.hpp"
#include "systems/LinearSecondOrderSystem.hpp"

#include <cmath>
#include <memory>
#include <sstream>

namespace mfwave::planewave {
namespace {

template <int D>
Outcome run(const Settings& s) {
  Stopwatch clock;
  const Real dx = 1.0 / s.cells;
  const MethodLatticeStencil<D> stencil = latticeMethodStencil<D>(s.method, s.lattice, dx, "study.method");
  const auto op = makePeriodicLatticeOperator<D>(stencil.acceleration, dx, s.cells, stencil.mass);
  const int c = op.components();
  if (c == 1 && s.shear) throw InputError("study.polarisation", "the scalar finite difference has no S wave");
  if (D == 1 && s.shear) throw InputError("study.polarisation", "there is no S wave in 1-D");

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
  // The limit is exact here (the whole spectrum is known), so a step beyond the integrator's own
  // limit L / omega_max (integrators/StabilityLimit) is refused before any work: round-off would
  // seed the growing modes and a short run could still look accurate.
  const StepVerdict verdict = judgeStep(s.integrator, {}, std::sqrt(extremes.largestOmegaSquared),
                                        s.cfl * record.stableTimeStep);
  if (verdict.aboveLimit)
    throw InputError("integrator.cfl", std::to_string(s.cfl) + " is beyond the " + verdict.limit.integrator +
                                           " limit " + std::to_string(verdict.limit.omegaDtLimit) +
                                           " / omega_max = " + std::to_string(verdict.limitDt) +
                                           " of this spectrum (cfl <= " +
                                           std::to_string(verdict.limitDt / record.stableTimeStep) + ")");

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
  const PlaneWave<D> wave(k, e, speed);
  record.simulatedTime = s.periods * wave.period();
  const Real steps = std::ceil(record.simulatedTime / (s.cfl * record.stableTimeStep) - 1e-9);
  std::ostringstream what;
  what << s.periods << " periods at cfl " << s.cfl;
  const std::string tooMany = tooManySteps(steps, what.str());
  if (!tooMany.empty()) throw InputError("study.periods", tooMany);
  record.steps = static_cast<long>(steps);
  record.timeStep = record.simulatedTime / static_cast<Real>(record.steps);

  // Nodal values of the exact field; collocation unknowns are coefficients d with M d = u.
  const Index nodes = op.nodes();
  record.particles = nodes;
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
  clock.restart();
  // A growing field stops the run at once: every 16 steps, anything non-finite or a thousand times
  // the initial amplitude (the exact wave keeps its amplitude) is a blow-up.
  const Real limit = 1e3 * std::max<Real>(u0.cwiseAbs().maxCoeff(), 1e-300);
  for (long step = 1; step <= record.steps; ++step) {
    integrator->step();
    if (step % 16 != 0 && step != record.steps) continue;
    const Vector& d = integrator->state().displacement;
    Index worst = 0;
    const Real largest = d.cwiseAbs().maxCoeff(&worst);
    if (!std::isfinite(largest) || largest > limit)
      throw InstabilityError("planewave: the field grew to " + std::to_string(largest) + " (initial amplitude " +
                                 std::to_string(u0.cwiseAbs().maxCoeff()) + ") by step " + std::to_string(step) +
                                 ", t = " + std::to_string(integrator->time()) + ", at node " +
                                 std::to_string(worst / c) + ": the step is beyond the integrator's limit",
                             step, integrator->time(), static_cast<long>(worst / c));
  }
  record.loopSeconds = clock.seconds();
  const Vector& d = integrator->state().displacement;
  const Vector u = op.lumped() ? Vector(d) : Vector(matrixSystem->mass() * d);
  const Vector exact = nodal(record.simulatedTime, false);
  out.error = (u - exact).norm() / exact.norm();
  record.name = s.method + " " + std::to_string(s.dimension) + "-D, " + std::to_string(s.cells) + " cells, " +
                    s.integrator;
  record.errors = {{"relative_l2_u", out.error}};
  record.primaryError = "relative_l2_u";
  return out;
}

}  // namespace

Outcome runPlaneWave(const Settings& s) {
  if (s.dimension == 1) return run<1>(s);
  if (s.dimension == 2) return run<2>(s);
  return run<3>(s);
}

}  // namespace mfwave::planewave
