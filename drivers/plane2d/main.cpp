// plane2d: 2-D plane-strain elastodynamics on the unit square by RK collocation, against a
// manufactured solution u_1 = u_2 = sin(pi x) sin(pi y) cos(w t) (zero displacement on every side)
// with the body force f = rho u_tt - L u it needs. Refinement in h at a fixed a / h; central
// difference on the constrained system at a fixed fraction of the critical step (power iteration
// on K), or implicit Newmark. Results: docs/studies/rkcm.md.
//
//   plane2d --scene data/scenes/plane2d.toml [--set 'study.cells=[8,16]'] [--out DIR]

#include "analysis/ConvergenceOrders.hpp"
#include "analysis/InteriorStability.hpp"
#include "analysis/MethodLatticeStencils.hpp"
#include "core/Error.hpp"
#include "core/Stopwatch.hpp"
#include "io/run/CaseTable.hpp"
#include "io/run/DriverCommandLine.hpp"
#include "io/run/RunDriver.hpp"
#include "io/run/SceneDriver.hpp"
#include "io/run/RunSummary.hpp"
#include "io/run/StudyCases.hpp"
#include "io/scene/LoadScene.hpp"
#include "io/scene/StepLimitCheck.hpp"
#include "io/scene/Scene.hpp"
#include "integrators/ConstrainedIntegrators.hpp"
#include "methods/collocation/CollocationSystem.hpp"
#include "methods/collocation/ConstrainedCollocationSystem.hpp"
#include "methods/collocation/ReproducingKernelShapeFunctions.hpp"
#include "observers/StabilityMonitor.hpp"
#include "observers/TimeLoop.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

using namespace mfwave;

namespace {

const char* kProgram = "plane2d";

SceneSchema plane2dSchema() {
  SceneSchema schema = SceneSchema::common();
  schema.addChoice("method.name", "reproducing_kernel");
  schema.add("method.order", ValueType::Integer).withUnit("-").defaultsTo("2").between(2, 3)
      .describedAs("RK basis order m (collocation needs second derivatives: m >= 2)");
  schema.add("method.support_ratio", ValueType::Number).withUnit("-").defaultsTo("2.5").positive()
      .describedAs("cubic B-spline support radius a / h (above about 2.7 the 2-D interior rows have growing modes: "
                   "refused)");
  schema.add("study", ValueType::Table).describedAs("the convergence study of plane2d");
  schema.add("study.cells", ValueType::NumberArray).withUnit("-").required()
      .describedAs("resolutions: cells per side (h = side / cells); geometry.spacing is ignored");
  schema.add("study.angular_frequency", ValueType::Number).withUnit("1/s").defaultsTo("6.283185307179586")
      .positive().describedAs("w of the manufactured solution");
  return schema;
}

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

struct CaseResult : StudyCase {
  int cells = 0;
  Real h = 0;
  Real errorU = 0, errorV = 0;
  Real orderU = std::nan(""), orderV = std::nan("");
};

// convergence.csv and the terminal table, one column each.
CaseTable<CaseResult> convergenceTable() {
  using R = const CaseResult&;
  CaseTable<CaseResult> t;
  t.column("cells", [](R r) { return r.cells; }, TerminalColumn("cells", 6))
      .column("h [m]", [](R r) { return r.h; }, TerminalColumn("h", 10))
      .column("dt [s]", [](R r) { return r.record.timeStep; }, TerminalColumn("dt", 11))
      .column("critical_dt [s]", [](R r) { return r.record.stableTimeStep; })
      .column("steps", [](R r) { return r.record.steps; })
      .column("relative_l2_u", [](R r) { return r.errorU; }, TerminalColumn("L2(u)", 12).precision(3))
      .column("order_u", [](R r) { return r.orderU; }, TerminalColumn("order", 8).precision(3))
      .column("relative_l2_v", [](R r) { return r.errorV; }, TerminalColumn("L2(v)", 12).precision(3))
      .column("order_v", [](R r) { return r.orderV; }, TerminalColumn("order", 8).precision(3))
      .column("wall_time [s]", [](R r) { return r.record.loopSeconds; });
  return t;
}

// Largest |eigenvalue| of K by power iteration on a(U) = -K U (zero loads), a fixed start.
Real spectralRadius(ConstrainedCollocationSystem& system) {
  Vector x = Vector::LinSpaced(system.size(), 0.3, 1.7).array().sin(), y(system.size());
  Real lambda = 0;
  // a(U) = f/rho - K U with the body force f: K x = -(a(x) - a(0)) removes the load.
  Vector a0(system.size()), zero = Vector::Zero(system.size());
  system.acceleration(0, zero, zero, a0);
  for (int it = 0; it < 400; ++it) {
    system.acceleration(0, x, x, y);
    y = -(y - a0);
    const Real next = y.norm() / x.norm();
    x = y / y.norm();
    if (it > 20 && std::abs(next - lambda) < 1e-6 * next) {
      lambda = next;
      break;
    }
    lambda = next;
  }
  return lambda;
}

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
  const Real omegaMax = std::sqrt(spectralRadius(system));
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
  StabilityMonitor monitor(scene.stability.options(2));
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

// Before any step: the exact spectrum of the interior rows on a periodic lattice (at h = 1: with a / h
// fixed the rows scale as 1 / h^2, so one spectrum serves every resolution). omega^2 < 0 grows at
// every time step, whatever the integrator: RK collocation at a / h >= 3 in 2-D, where the mass
// symbol changes sign (docs/studies/spectra.md). Refused with exit 3 unless stability.allow_growth,
// which runs on and says so in the summary (the returned notes).
std::vector<std::string> checkInteriorStability(const Scene& scene, int order, Real ratio) {
  const MethodLatticeStencil<2> rows = collocationInteriorStencil<2>(CollocationBasis::ReproducingKernel, order, ratio,
                                                                     scene.material.material(), 1.0);
  const InteriorStability<2> verdict = interiorStability<2>(rows.acceleration, rows.mass, 1.0, 32);
  if (!verdict.growing()) return {};
  std::ostringstream what;
  what << "the RK collocation operator (method.order = " << order << ", method.support_ratio = " << ratio
       << ") has growing modes: its interior " << verdict.describe()
       << "; such a mode grows at every time step";
  return {refuseGrowingModes(scene.stability, what.str(), "a smaller method.support_ratio, e.g. 2.5, is stable in 2-D")};
}

}  // namespace

int main(int argc, char** argv) {
  const SceneSchema schema = plane2dSchema();
  DriverCommandLine cli(kProgram, "plane2d: plane-strain RK collocation against a manufactured solution; order in h",
                        schema.describe());
  if (const auto exit = cli.parse(argc, argv)) return *exit;
  return runDriver(kProgram, [&]() -> int {
    SceneReader reader = loadDriverScene(cli.options(), schema);
    const Scene scene = readScene(reader);
    if (scene.info.dimension != 2) reader.fail("scene.dimension", "plane2d is a 2-D study");
    if (scene.method.name != "reproducing_kernel") reader.fail("method.name", "plane2d uses reproducing_kernel");
    const std::vector<std::string> integrators = constrainedIntegratorNames();
    if (std::find(integrators.begin(), integrators.end(), scene.integrator.name) == integrators.end())
      reader.fail("integrator.name", "plane2d runs central_difference or newmark");
    if (!scene.loads.empty()) reader.fail("load", "plane2d sets its own body force");
    const int order = static_cast<int>(reader.integer("method.order"));
    const Real ratio = reader.number("method.support_ratio");
    const Real w = reader.number("study.angular_frequency");
    std::vector<int> cells;
    for (Real c : reader.numbers("study.cells")) {
      if (c != std::floor(c) || c < 4) reader.fail("study.cells", "each resolution must be a whole number >= 4");
      cells.push_back(static_cast<int>(c));
    }
    reader.checkAllKeysRead();
    std::vector<std::string> stabilityNotes = checkInteriorStability(scene, order, ratio);
    const std::string folder = prepareOutputFolder(cli.options(), scene.output.folder, reader);
    std::vector<CaseResult> results = runCases(
        cells, [&](int c) { return runCase(scene, order, ratio, w, c, stabilityNotes); }, !cli.options().quiet);
    storeObservedOrders(results, &CaseResult::h, &CaseResult::errorU, &CaseResult::orderU);
    storeObservedOrders(results, &CaseResult::h, &CaseResult::errorV, &CaseResult::orderV);
    const CaseTable<CaseResult> table = convergenceTable();
    table.writeCsv(folder + "/convergence.csv", results, 17);
    table.print(std::cout, results);
    RunSummary summary(kProgram, scene.info.name, scene.method.name, scene.integrator.name);
    summary.addCases(results);
    summary.totalsFromCases();
    const CaseResult& finest = results.back();
    summary.timeStep = finest.record.timeStep;
    summary.errors.push_back({"relative_l2_u_finest", finest.errorU});
    summary.errors.push_back({"relative_l2_v_finest", finest.errorV});
    if (results.size() > 1) summary.figures.push_back({"observed_order_u", finest.orderU});
    summary.notes.addAll(stabilityNotes);
    summary.simulatedTime = scene.integrator.endTime;
    summary.files.add("convergence.csv");
    summary.conclude(folder, &std::cout);
    return 0;
  });
}
