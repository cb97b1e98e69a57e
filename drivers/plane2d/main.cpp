// plane2d: 2-D plane-strain elastodynamics on the unit square by RK collocation, against a
// manufactured solution u_1 = u_2 = sin(pi x) sin(pi y) cos(w t) (zero displacement on every side)
// with the body force f = rho u_tt - L u it needs. Refinement in h at a fixed a / h; central
// difference on the constrained system at a fixed fraction of the critical step (power iteration
// on K), or implicit Newmark. Results: docs/studies/rkcm.md.
//
//   plane2d --scene data/scenes/plane2d.toml [--set 'study.cells=[8,16]'] [--out DIR]

#include "studies/plane2d/Plane2dCase.hpp"

#include "numerics/ConvergenceOrders.hpp"
#include "core/Error.hpp"
#include "integrators/ConstrainedIntegrators.hpp"
#include "io/run/CaseTable.hpp"
#include "io/run/DriverCommandLine.hpp"
#include "io/run/MemoryGuard.hpp"
#include "io/run/RunDriver.hpp"
#include "io/run/SceneDriver.hpp"
#include "io/run/RunSummary.hpp"
#include "io/run/StudyCases.hpp"
#include "io/scene/Format.hpp"
#include "io/scene/LoadScene.hpp"
#include "io/scene/Scene.hpp"
#include "wiring/CollocationSpec.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

using namespace mfwave;
using namespace mfwave::plane2d;

namespace {

const char* kProgram = "plane2d";

SceneSchema plane2dSchema() {
  SceneSchema schema = SceneSchema::common();
  CollocationKeyDefaults collocation;
  collocation.supportRatio = 2.5;
  collocation.supportAdvice = "above about 2.7 the 2-D interior rows have growing modes: refused";
  addCollocationKeys(schema, collocation);
  schema.add("study", ValueType::Table).describedAs("the convergence study of plane2d");
  schema.add("study.cells", ValueType::NumberArray).withUnit("-").required()
      .describedAs("resolutions: cells per side (h = side / cells); geometry.spacing is ignored");
  schema.add("study.angular_frequency", ValueType::Number).withUnit("1/s").defaultsTo("6.283185307179586")
      .positive().describedAs("w of the manufactured solution");
  return schema;
}

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
      if (c > 2000) reader.fail("study.cells", "at most 2000 cells per side (4 million nodes), got " + scene::formatNumber(c));
      // RK collocation in 2-D: 21 KiB per node measured (the tradeoff sweep's largest lamb2d run), 1.5 x.
      const std::string why = memoryRefusal(scene::formatNumber(c) + " cells per side",
                                            {(c + 1) * (c + 1), 32768, "RK collocation in 2-D, 21 KiB measured"});
      if (!why.empty()) reader.fail("study.cells", why);
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
