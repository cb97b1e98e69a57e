#include "Plane2dCase.hpp"

#include "numerics/StableTimeStep.hpp"
#include "core/Error.hpp"
#include "core/Stopwatch.hpp"
#include "integrators/ConstrainedIntegrators.hpp"
#include "io/scene/StepLimitCheck.hpp"
#include "methods/collocation/CollocationSystem.hpp"
#include "methods/collocation/ConstrainedCollocationSystem.hpp"
#include "methods/collocation/ReproducingKernelShapeFunctions.hpp"
#include "observers/StabilityMonitor.hpp"
#include "observers/TimeLoop.hpp"
#include "wiring/CollocationSpec.hpp"

#include <limits>
#include <memory>

namespace mfwave::plane2d {
namespace {

struct Manufactured {
  Material m;
  Real w;
  Real phi(const Vec2& x) const { return std::sin(kPi * x[0]) * std::sin(kPi * x[1]); }
  Vec2 u(const Vec2& x, Real t) const { return Vec2::Constant(phi(x) * std::cos(w * t)); }
  Vec2 v(const Vec2& x, Real t) const { return Vec2::Constant(-w * phi(x) * std::sin(w * t)); }
  // f = rho u_tt - L u, L u_i = mu Lap u_i + (lambda + mu) d_i div u.
  Vec2 f(const Vec2& x, Real t) const {
    const Real p = phi(x), c = std::cos(kPi * x[0]) * std::cos(kPi * x[1]), pi2 = kPi * kPi;
    const Real lu = m.mu() * (-2 * pi2 * p) + (m.lambda() + m.mu()) * (-pi2 * p + pi2 * c);
    return Vec2::Constant((-m.density() * w * w * p - lu) * std::cos(w * t));
  }
};

}  // namespace

CaseResult runCase(const Scene& scene, int order, Real ratio, Real w, int cells, std::vector<std::string>& notes) {
  const Stopwatch setup;
  const Vec2 lo(scene.geometry.lower[0], scene.geometry.lower[1]);
  const Real side = scene.geometry.upper[0] - lo[0];
  if (std::abs(scene.geometry.upper[1] - lo[1] - side) > 1e-12 * side)
    throw InputError("geometry.upper", "plane2d needs a square");
  const Real h = side / cells;
  const Material material = scene.material.material();
  Manufactured exact{material, w};
  Coordinates<2> nodes;
  CollocationPoints<2> points;
  for (int j = 0; j <= cells; ++j)
    for (int i = 0; i <= cells; ++i) {
      const Vec2 x(lo[0] + side * i / cells, lo[1] + side * j / cells);
      nodes[0].push_back(x[0]);
      nodes[1].push_back(x[1]);
      const bool edge = i == 0 || j == 0 || i == cells || j == cells;
      points.add(x, edge ? CollocationRowKind::Displacement : CollocationRowKind::Interior);
    }
  // The manufactured field lives on [0, 1]^2: points are mapped into it by (x - lower) / side.
  const ReproducingKernelShapeFunctions<2> shapes(nodes, order, ratio * h);
  CollocationLoads<2> loads;
  loads.bodyForce = [&exact, lo, side](const Vec2& x, Real t) { return exact.f((x - lo) / side, t); };
  ConstrainedCollocationSystem system(assembleCollocation<2>(shapes, points, material, loads));

  // The step against the integrator's own limit on this operator (exit 2 above it, before stepping).
  const Real omegaMax = std::sqrt(accelerationSpectralRadius(system).value);
  const Real criticalDt = 2 / omegaMax;
  const Real dt = scene.integrator.timeStepFor(criticalDt);
  const StepLimitCheck check = checkStepLimit(scene.integrator, scene.stability, omegaMax, dt, criticalDt,
                                              "a power iteration on the assembled operator",
                                              "at " + std::to_string(cells) + " cells");
  if (!check.note.empty()) notes.push_back(check.note);
  Vector U0(system.size()), V0(system.size());
  for (Index r = 0; r < system.size(); r += 2) {
    const Vec2 x = (points.points[static_cast<std::size_t>(system.interiorRows()[static_cast<std::size_t>(r)] / 2)] - lo) / side;
    U0.segment<2>(r) = exact.u(x, 0);
    V0.segment<2>(r) = exact.v(x, 0);
  }
  const std::unique_ptr<SecondOrderIntegrator> integrator =
      makeConstrainedIntegrator(scene.integrator.name, scene.integrator.options);
  integrator->initialise(system, 0, U0, V0, dt);
  // The manufactured body force acts throughout: growth is judged at the grid scale only.
  StabilityMonitor monitor(scene.stability.options(2, std::numeric_limits<Real>::infinity()));
  TimeLoop loop;
  loop.add(monitor);
  const double setupSeconds = setup.seconds();
  const RunStatistics stats = loop.run(*integrator, scene.integrator.endTime);

  // Relative L2 errors on a 4x finer uniform grid (trapezoidal weights).
  const int n = 4 * cells;
  std::vector<Vec2> grid;
  std::vector<Real> weight;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      grid.emplace_back(lo[0] + side * i / n, lo[1] + side * j / n);
      weight.push_back((i == 0 || i == n ? 0.5 : 1.0) * (j == 0 || j == n ? 0.5 : 1.0));
    }
  const StateView s = integrator->state();
  const Vector u = evaluateCollocationField<2>(shapes, system.coefficients(s.displacement, s.time), grid);
  const Vector v = evaluateCollocationField<2>(shapes, system.coefficientRates(s.velocity, s.time), grid);
  Real eu = 0, nu = 0, ev = 0, nv = 0;
  for (std::size_t p = 0; p < grid.size(); ++p) {
    const Vec2 x = (grid[p] - lo) / side;
    eu += weight[p] * (u.segment<2>(static_cast<Index>(p) * 2) - exact.u(x, s.time)).squaredNorm();
    nu += weight[p] * exact.u(x, s.time).squaredNorm();
    ev += weight[p] * (v.segment<2>(static_cast<Index>(p) * 2) - exact.v(x, s.time)).squaredNorm();
    nv += weight[p] * exact.v(x, s.time).squaredNorm();
  }
  CaseResult result;
  result.cells = cells;
  result.h = h;
  result.errorU = std::sqrt(eu / nu);
  result.errorV = std::sqrt(ev / nv);
  CaseRecord& record = result.record;
  record.name = std::to_string(cells) + " cells";
  record.particles = (cells + 1) * (cells + 1);
  result.recordLoop(stats);
  record.timeStep = dt;
  record.stableTimeStep = criticalDt;
  record.simulatedTime = scene.integrator.endTime;
  record.setupSeconds = setupSeconds;
  record.errors = {{"relative_l2_u", result.errorU}, {"relative_l2_v", result.errorV}};
  record.primaryError = "relative_l2_u";
  return result;
}

std::vector<std::string> checkInteriorStability(const Scene& scene, int order, Real ratio) {
  const CollocationGrowingModes modes = rkPlaneStrainGrowingModes(order, ratio, scene.material.material());
  if (!modes.growing()) return {};
  return {refuseGrowingModes(scene.stability, modes.what, modes.advice)};
}

}  // namespace mfwave::plane2d
