// bar1d: the Luo-Liu-Huang example. A bar on [0, 10] (rho = 1, E = 10, c = sqrt 10), fixed at
// x = 0, free at x = 10, at rest and undeformed but moving with v0 = -1 at t = 0, discretised by
// reproducing-kernel (or radial-basis) strong-form collocation with Ns = Nc uniform nodes, advanced
// by central difference on the constrained system (Newmark beta = 0) or implicit Newmark.
//
// What it shows: the error against the exact solution by characteristics (FixedFreeBarImpact) and
// its convergence in h. The exact velocity is discontinuous, so low orders are expected.
// Results: docs/studies/rkcm.md.
//
//   bar1d --scene data/scenes/bar1d.toml [--set 'study.nodes=[21,41,81]'] [--out DIR]

#include "analysis/CollocationStability.hpp"
#include "analysis/ConvergenceOrders.hpp"
#include "analytic/FixedFreeBarImpact.hpp"
#include "core/AtomicFile.hpp"
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
#include "methods/collocation/RadialBasisFunction.hpp"
#include "observers/StabilityMonitor.hpp"
#include "observers/TimeLoop.hpp"
#include "observers/TimeSeries.hpp"
#include "study/CollocationSpec.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

using namespace mfwave;

namespace {

const char* kProgram = "bar1d";

SceneSchema bar1dSchema() {
  SceneSchema schema = SceneSchema::common();
  schema.addChoice("method.name", "reproducing_kernel");
  schema.addChoice("method.name", "radial_basis");
  schema.add("method.order", ValueType::Integer).withUnit("-").defaultsTo("2").between(0, 3)
      .when("name = reproducing_kernel").describedAs("RK basis order m");
  schema.add("method.support_ratio", ValueType::Number).withUnit("-").defaultsTo("3.3").positive()
      .when("name = reproducing_kernel").describedAs("cubic B-spline support radius a / h");
  schema.add("method.basis", ValueType::String).defaultsTo("\"inverse_multiquadric\"")
      .oneOf(radialBasisNames()).when("name = radial_basis").describedAs("radial basis function");
  schema.add("method.shape_ratio", ValueType::Number).withUnit("-").defaultsTo("1.0").positive()
      .when("name = radial_basis").describedAs("RBF shape parameter a_r / h");
  schema.add("study", ValueType::Table).describedAs("the convergence study of bar1d");
  schema.add("study.initial_velocity", ValueType::Number).withUnit("m/s").defaultsTo("-1.0")
      .describedAs("uniform initial velocity v0");
  schema.add("study.nodes", ValueType::NumberArray).withUnit("-").required()
      .describedAs("resolutions: numbers of nodes Ns = Nc (uniform, h = L / (Ns - 1)); geometry.spacing is ignored");
  schema.add("study.error_points", ValueType::Integer).withUnit("-").defaultsTo("2001").atLeast(11)
      .describedAs("uniform points where the L2 errors are evaluated");
  schema.add("study.error_samples", ValueType::Integer).withUnit("-").defaultsTo("50").atLeast(1)
      .describedAs("times (evenly spread) at which the error over time is sampled");
  return schema;
}

struct Study {
  Scene scene;
  CollocationSpec method;
  Real v0 = -1;
  std::vector<int> nodes;
  int errorPoints = 2001;
  int errorSamples = 50;
};

struct CaseResult : StudyCase {
  int nodes = 0;
  Real h = 0;
  Real errorU = 0, errorV = 0, maxErrorU = 0;
  Real orderU = std::nan(""), orderV = std::nan("");
};

// convergence.csv and the terminal table, one column each.
CaseTable<CaseResult> convergenceTable() {
  using R = const CaseResult&;
  CaseTable<CaseResult> t;
  t.column("nodes", [](R r) { return r.nodes; }, TerminalColumn("nodes", 6))
      .column("h [m]", [](R r) { return r.h; }, TerminalColumn("h", 10))
      .column("dt [s]", [](R r) { return r.record.timeStep; }, TerminalColumn("dt", 10))
      .column("critical_dt [s]", [](R r) { return r.record.stableTimeStep; }, TerminalColumn("dt_crit", 12))
      .column("steps", [](R r) { return r.record.steps; })
      .column("relative_l2_u", [](R r) { return r.errorU; }, TerminalColumn("L2(u)", 12).precision(3))
      .column("order_u", [](R r) { return r.orderU; }, TerminalColumn("order", 8).precision(3))
      .column("relative_l2_v", [](R r) { return r.errorV; }, TerminalColumn("L2(v)", 12).precision(3))
      .column("order_v", [](R r) { return r.orderV; }, TerminalColumn("order", 8).precision(3))
      .column("max_relative_l2_u_over_time", [](R r) { return r.maxErrorU; },
              TerminalColumn("max_t L2(u)", 12).precision(3))
      .column("wall_time [s]", [](R r) { return r.record.loopSeconds; });
  return t;
}

// Relative L2 errors of u and v at time t (trapezoidal sums on uniform points).
struct Errors {
  Real u, v, uNorm, vNorm;
};

class ErrorSampler : public Observer {
 public:
  ErrorSampler(const ConstrainedCollocationSystem& system, const ShapeFunctions<1>& shapes,
               const FixedFreeBarImpact& exact, std::vector<Vec1> points, long every)
      : system_(system), shapes_(shapes), exact_(exact), points_(std::move(points)), every_(every),
        series_("t [s]", {"relative_l2_u", "relative_l2_v", "l2_u_error [m]", "l2_u [m]"}) {}

  Errors errors(const StateView& s) const {
    const Vector u = evaluateCollocationField<1>(shapes_, system_.coefficients(s.displacement, s.time), points_);
    const Vector v = evaluateCollocationField<1>(shapes_, system_.coefficientRates(s.velocity, s.time), points_);
    Errors e{0, 0, 0, 0};
    for (std::size_t i = 0; i < points_.size(); ++i) {
      const Real x = points_[i][0], w = (i == 0 || i + 1 == points_.size()) ? 0.5 : 1.0;
      const Real ue = exact_.displacement(x, s.time), ve = exact_.velocity(x, s.time);
      e.u += w * std::pow(u[static_cast<Index>(i)] - ue, 2);
      e.v += w * std::pow(v[static_cast<Index>(i)] - ve, 2);
      e.uNorm += w * ue * ue;
      e.vNorm += w * ve * ve;
    }
    return e;
  }
  void observe(const StateView& s) override {
    (void)every_;
    const Errors e = errors(s);
    maxU_ = std::max(maxU_, e.uNorm);
    maxErrU_ = std::max(maxErrU_, e.u);
    series_.append(s.time, {std::sqrt(e.u / std::max(e.uNorm, 1e-300)), std::sqrt(e.v / std::max(e.vNorm, 1e-300)),
                            std::sqrt(e.u), std::sqrt(e.uNorm)});
  }
  void end(const StateView& s) override { observe(s); }
  // max over sampled times of ||e_u|| / max over sampled times of ||u||.
  Real maxRelativeU() const { return std::sqrt(maxErrU_ / std::max(maxU_, 1e-300)); }
  const TimeSeries& series() const { return series_; }

 private:
  const ConstrainedCollocationSystem& system_;
  const ShapeFunctions<1>& shapes_;
  const FixedFreeBarImpact& exact_;
  std::vector<Vec1> points_;
  long every_;
  Real maxU_ = 0, maxErrU_ = 0;
  TimeSeries series_;
};

CaseResult runCase(const Study& study, int nodeCount, const std::string& folder, bool writeSeries) {
  const Stopwatch setup;
  const Scene& scene = study.scene;
  const Real x0 = scene.geometry.lower[0], length = scene.geometry.upper[0] - x0;
  const Real h = length / (nodeCount - 1);
  const Material material = Material::fromYoung(scene.material.material().youngsModulus(), 0,
                                                scene.material.density);
  const FixedFreeBarImpact exact(length, material.barSpeed(), study.v0);

  Coordinates<1> nodes;
  for (int i = 0; i < nodeCount; ++i) nodes[0].push_back(x0 + length * i / (nodeCount - 1));
  const auto shapes = makeCollocationShapes<1>(study.method, nodes, h);
  ConstrainedCollocationSystem system(assembleCollocation<1>(*shapes, fixedFreeBarPoints(nodes), material));

  // Before stepping, the whole operator's spectrum (dense: a 1-D bar has few nodes). Complex or
  // negative eigenvalues are modes that grow at any step: refused (exit 3) naming the growth rate,
  // unless stability.allow_growth. The exact central-difference step is 2 / sqrt(max |eig K|), and
  // every integrator's step is checked against its own limit (io/scene/StepLimitCheck).
  const EigenvalueStability spectrum = eigenvalueStability(system.denseStiffness());
  const std::string where = "at " + std::to_string(nodeCount) + " nodes";
  std::string note;
  if (spectrum.unconditionallyUnstable)
    note = refuseGrowingModes(scene.stability,
                              "the collocation operator " + where + " has growing modes: " + spectrum.verdict() +
                                  " (" + study.method.describe() + ")",
                              "see the stability atlas, docs/studies/stability-atlas.md");
  const Real lambdaMax = spectrum.largestModulus;
  const Real criticalDt = 2 / std::sqrt(lambdaMax);
  const Real dt = scene.integrator.timeStepFor(criticalDt);
  const StepLimitCheck check = checkStepLimit(scene.integrator, scene.stability, std::sqrt(lambdaMax), dt, criticalDt,
                                              "the exact spectrum of the collocation operator", where);
  if (!check.note.empty()) note += (note.empty() ? "" : "; ") + check.note;

  // Initial state at interior points: u = 0, v = v0 (the boundary rows enforce u(0) = 0).
  const Vector U0 = Vector::Zero(system.size());
  const Vector V0 = Vector::Constant(system.size(), study.v0);
  const std::unique_ptr<SecondOrderIntegrator> integrator =
      makeConstrainedIntegrator(scene.integrator.name, scene.integrator.options);
  integrator->initialise(system, 0, U0, V0, dt);

  std::vector<Vec1> errorPoints;
  for (int i = 0; i < study.errorPoints; ++i) errorPoints.emplace_back(x0 + length * i / (study.errorPoints - 1));
  const long steps = scene.integrator.stepsFor(criticalDt);
  const long every = std::max<long>(1, steps / study.errorSamples);
  ErrorSampler sampler(system, *shapes, exact, errorPoints, every);
  StabilityMonitor monitor(scene.stability.options(1));
  TimeLoop loop;
  loop.add(monitor);
  loop.add(sampler, every);
  const double setupSeconds = setup.seconds();
  const RunStatistics stats = loop.run(*integrator, scene.integrator.endTime);

  const Errors e = sampler.errors(integrator->state());
  CaseResult result;
  result.nodes = nodeCount;
  result.h = h;
  result.errorU = std::sqrt(e.u / e.uNorm);
  result.errorV = std::sqrt(e.v / e.vNorm);
  result.maxErrorU = sampler.maxRelativeU();
  if (!note.empty()) result.notes.push_back(note);
  CaseRecord& record = result.record;
  record.name = std::to_string(nodeCount) + " nodes";
  record.particles = nodeCount;
  result.recordLoop(stats);
  record.timeStep = dt;
  record.stableTimeStep = criticalDt;
  record.simulatedTime = scene.integrator.endTime;
  record.setupSeconds = setupSeconds;
  record.errors = {{"relative_l2_u", result.errorU},
                   {"relative_l2_v", result.errorV},
                   {"max_relative_l2_u_over_time", result.maxErrorU}};
  record.primaryError = "relative_l2_u";
  if (writeSeries) {
    const std::string name = "nodes-" + std::to_string(nodeCount);
    const std::string stem = folder + "/" + name;
    sampler.series().writeCsv(stem + "-errors.csv");
    const StateView s = integrator->state();
    const Vector u = evaluateCollocationField<1>(*shapes, system.coefficients(s.displacement, s.time), errorPoints);
    const Vector v = evaluateCollocationField<1>(*shapes, system.coefficientRates(s.velocity, s.time), errorPoints);
    AtomicFile profile(stem + "-profile.csv");
    profile.stream() << "x [m],u [m],u_exact [m],v [m/s],v_exact [m/s]\n" << std::setprecision(10);
    for (std::size_t i = 0; i < errorPoints.size(); ++i) {
      const Real x = errorPoints[i][0];
      profile.stream() << x << ',' << u[static_cast<Index>(i)] << ',' << exact.displacement(x, s.time) << ','
                       << v[static_cast<Index>(i)] << ',' << exact.velocity(x, s.time) << '\n';
    }
    profile.commit();
    result.files = {name + "-errors.csv", name + "-profile.csv"};
  }
  return result;
}

Study readStudy(SceneReader& reader) {
  Study study;
  study.scene = readScene(reader);
  if (study.scene.info.dimension != 1) reader.fail("scene.dimension", "bar1d is a 1-D study");
  study.method = readCollocationSpec(reader, study.scene.method.name, kProgram);
  if (facesWith(study.scene.boundaries, BoundaryType::Fixed) != 0x1 ||
      facesWith(study.scene.boundaries, BoundaryType::Traction) != 0)
    reader.fail("boundary", "bar1d is the fixed-free bar: faces = [\"-x\"], type = \"fixed\"; +x free");
  if (!study.scene.loads.empty()) reader.fail("load", "bar1d takes no loads");
  const std::vector<std::string> integrators = constrainedIntegratorNames();
  if (std::find(integrators.begin(), integrators.end(), study.scene.integrator.name) == integrators.end())
    reader.fail("integrator.name", "bar1d runs central_difference or newmark");
  study.v0 = reader.number("study.initial_velocity");
  for (Real n : reader.numbers("study.nodes")) {
    if (n != std::floor(n) || n < 6) reader.fail("study.nodes", "each resolution must be a whole number >= 6");
    study.nodes.push_back(static_cast<int>(n));
  }
  study.errorPoints = static_cast<int>(reader.integer("study.error_points"));
  study.errorSamples = static_cast<int>(reader.integer("study.error_samples"));
  return study;
}

}  // namespace

int main(int argc, char** argv) {
  const SceneSchema schema = bar1dSchema();
  DriverCommandLine cli(kProgram, "bar1d: the Luo-Liu-Huang fixed-free bar by RK / RBF collocation; convergence in h",
                        schema.describe());
  if (const auto exit = cli.parse(argc, argv)) return *exit;

  return runDriver(kProgram, [&]() -> int {
    SceneReader reader = loadDriverScene(cli.options(), schema);
    const Study study = readStudy(reader);
    reader.checkAllKeysRead();
    const std::string folder = prepareOutputFolder(cli.options(), study.scene.output.folder, reader);
    std::vector<CaseResult> results =
        runCases(study.nodes, [&](int nodes) { return runCase(study, nodes, folder, true); }, !cli.options().quiet);
    storeObservedOrders(results, &CaseResult::h, &CaseResult::errorU, &CaseResult::orderU);
    storeObservedOrders(results, &CaseResult::h, &CaseResult::errorV, &CaseResult::orderV);
    const CaseTable<CaseResult> table = convergenceTable();
    table.writeCsv(folder + "/convergence.csv", results, 17);
    table.print(std::cout, results);
    RunSummary summary(kProgram, study.scene.info.name, study.scene.method.name, study.scene.integrator.name);
    summary.addCases(results);
    for (const CaseResult& r : results) summary.notes.addAll(r.notes);
    summary.totalsFromCases();
    const CaseResult& finest = results.back();
    summary.timeStep = finest.record.timeStep;
    summary.errors.push_back({"relative_l2_u_finest", finest.errorU});
    summary.errors.push_back({"relative_l2_v_finest", finest.errorV});
    summary.errors.push_back({"max_relative_l2_u_over_time_finest", finest.maxErrorU});
    summary.figures.push_back({"critical_dt_first", results.front().record.stableTimeStep});
    if (results.size() > 1) summary.figures.push_back({"observed_order_u", finest.orderU});
    summary.simulatedTime = study.scene.integrator.endTime;
    summary.notes.add("particles: nodes of the finest case; steps and wall time summed over all cases");
    summary.files.add("convergence.csv");
    summary.mergeNotesAndFiles(results);
    summary.conclude(folder, &std::cout);
    return 0;
  });
}
