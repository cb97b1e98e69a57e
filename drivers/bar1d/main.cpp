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

#include "studies/bar1d/BarCollocationCase.hpp"

#include "numerics/ConvergenceOrders.hpp"
#include "core/Error.hpp"
#include "integrators/ConstrainedIntegrators.hpp"
#include "io/run/CaseTable.hpp"
#include "io/run/DriverCommandLine.hpp"
#include "io/run/RunDriver.hpp"
#include "io/run/SceneDriver.hpp"
#include "io/run/RunSummary.hpp"
#include "io/run/StudyCases.hpp"
#include "io/scene/Format.hpp"
#include "io/scene/LoadScene.hpp"
#include "io/scene/Scene.hpp"
#include "methods/collocation/RadialBasisFunction.hpp"
#include "wiring/CollocationSpec.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

using namespace mfwave;
using namespace mfwave::bar1d;

namespace {

const char* kProgram = "bar1d";

SceneSchema bar1dSchema() {
  SceneSchema schema = SceneSchema::common();
  // The paper's supports: a / h = 3.3 for the reproducing kernel, a_r / h = 1 for the radial basis.
  CollocationKeyDefaults collocation;
  collocation.supportRatio = 3.3;
  collocation.radialBasis = true;
  collocation.shapeRatio = 1.0;
  addCollocationKeys(schema, collocation);
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
    if (n > 20000)  // the operator's whole spectrum is taken dense: n^2 memory, n^3 time
      reader.fail("study.nodes", "at most 20000 nodes (the dense spectrum of the operator), got " + scene::formatNumber(n));
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
