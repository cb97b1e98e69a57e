// wave1d: standing waves in a fixed-fixed bar, u_tt = c^2 u_xx, discretised on a line of
// particles by the reference finite-difference operator and advanced by each integrator.
//
// What it shows: the whole pipeline (lattice -> neighbours -> operator -> integrator ->
// observers) against an exact solution, the convergence order in dx at a fixed CFL fraction, and
// the cost of each integrator for a given error. Results: docs/studies/wave1d.md.
//
//   wave1d --scene data/scenes/wave1d.toml [--set study.cells=[16,32]] [--out DIR]

#include "studies/wave1d/Wave1dCase.hpp"

#include "numerics/ConvergenceOrders.hpp"
#include "core/Error.hpp"
#include "integrators/IntegratorFactory.hpp"
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

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

using namespace mfwave;
using namespace mfwave::wave1d;

namespace {

const char* kProgram = "wave1d";

SceneSchema wave1dSchema() {
  SceneSchema schema = SceneSchema::common();
  schema.add("study", ValueType::Table).describedAs("the convergence study of wave1d");
  schema.add("study.mode", ValueType::Integer).withUnit("-").defaultsTo("1").atLeast(1).describedAs(
      "standing-wave mode number n: u = sin(n pi x / L) cos(n pi c t / L)");
  schema.add("study.cells", ValueType::NumberArray)
      .withUnit("-")
      .required()
      .describedAs("resolutions, in cells along the bar (each at least 4 per half wave); geometry.spacing is ignored");
  schema.add("study.integrators", ValueType::StringArray)
      .withUnit("-")
      .defaultsTo("[\"central_difference\", \"leapfrog\", \"newmark\", \"arkode\"]")
      .describedAs("integrators to compare (names as integrator.name)");
  return schema;
}

// convergence.csv and the terminal table, one column each.
CaseTable<CaseResult> convergenceTable() {
  using R = const CaseResult&;
  CaseTable<CaseResult> t;
  t.column("integrator", [](R r) { return r.integrator; }, TerminalColumn("integrator", 20).left())
      .column("cells", [](R r) { return r.cells; }, TerminalColumn("cells", 7))
      .column("dx [m]", [](R r) { return r.dx; })
      .column("dt [s]", [](R r) { return r.record.timeStep; }, TerminalColumn("dt", 10).precision(3))
      .column("steps", [](R r) { return r.record.steps; })
      .column("relative_l2_error", [](R r) { return r.error; }, TerminalColumn("L2 error", 13).scientific().precision(3))
      .column("observed_order", [](R r) { return r.order; }, TerminalColumn("order", 8).precision(3))
      .column("energy_drift", [](R r) { return r.energyDrift; }, TerminalColumn("energy", 12).scientific().precision(2))
      .column("wall_time [s]", [](R r) { return r.record.loopSeconds; }, TerminalColumn("wall [s]", 11).precision(3))
      .column("particle_steps_per_s", [](R r) { return r.record.particleStepsPerSecond(); },
              TerminalColumn("part-steps/s", 14).scientific().precision(2));
  return t;
}

Study readStudy(SceneReader& reader) {
  Study study;
  study.scene = readScene(reader);
  if (study.scene.info.dimension != 1) reader.fail("scene.dimension", "wave1d is a 1-D study");
  if (study.scene.method.name != "finite_difference") reader.fail("method.name", "wave1d uses finite_difference");
  if (facesWith(study.scene.boundaries, BoundaryType::Fixed) != 0x3)
    reader.fail("boundary", "wave1d needs both ends fixed: faces = [\"-x\", \"+x\"], type = \"fixed\"");
  if (!study.scene.loads.empty()) reader.fail("load", "wave1d takes no loads: the standing wave is free");
  study.mode = static_cast<int>(reader.integer("study.mode"));
  for (Real c : reader.numbers("study.cells")) {
    if (c != std::floor(c) || c < 4 * study.mode)
      reader.fail("study.cells", "each resolution must be a whole number of at least 4 cells per half wave");
    if (c > 1e8) reader.fail("study.cells", "at most 1e8 cells, got " + scene::formatNumber(c));
    study.cells.push_back(static_cast<int>(c));
  }
  study.integrators = reader.strings("study.integrators");
  for (const auto& name : study.integrators) makeSecondOrderIntegrator(name, study.scene.integrator.options);
  refuseStepsAboveTheLimit(study);
  {
    // The finest case holds its line (about 150 bytes a cell: the operator, the state, the
    // integrators' vectors) and its probe and energy series (48 bytes a step); doubled for a margin.
    const Real cells = *std::max_element(study.cells.begin(), study.cells.end());
    const Scene& scene = study.scene;
    const Real dx = (scene.geometry.upper[0] - scene.geometry.lower[0]) / cells;
    const Real steps = scene.integrator.endTime / scene.integrator.timeStepFor(dx / scene.material.material().pWaveSpeed());
    const std::string why = memoryRefusal(mfwave::scene::formatNumber(cells) + " cells",
                                          {cells, 300 + 96 * steps / cells, "the line and its probe and energy series"});
    if (!why.empty()) reader.fail("study.cells", why);
  }
  return study;
}

}  // namespace

int main(int argc, char** argv) {
  const SceneSchema schema = wave1dSchema();
  DriverCommandLine cli(kProgram, "wave1d: standing wave in a fixed-fixed bar; convergence and cost of each integrator",
                        schema.describe());
  if (const auto exit = cli.parse(argc, argv)) return *exit;

  return runDriver(kProgram, [&]() -> int {
    SceneReader reader = loadDriverScene(cli.options(), schema);
    const Study study = readStudy(reader);
    reader.checkAllKeysRead();  // unknown keys: before any work
    const std::string folder = prepareOutputFolder(cli.options(), study.scene.output.folder, reader);

    // Every integrator at every resolution; the finest of each writes its time series.
    struct Planned {
      std::string integrator;
      int cells;
      bool writeSeries;
    };
    std::vector<Planned> plan;
    for (const auto& name : study.integrators)
      for (std::size_t r = 0; r < study.cells.size(); ++r)
        plan.push_back({name, study.cells[r], r + 1 == study.cells.size()});
    std::vector<CaseResult> results = runCases(
        plan, [&](const Planned& c) { return runCase(study, c.integrator, c.cells, folder, c.writeSeries); },
        !cli.options().quiet);

    const auto sameIntegrator = [](const CaseResult& a, const CaseResult& b) { return a.integrator == b.integrator; };
    storeObservedOrders(results, &CaseResult::dx, &CaseResult::error, &CaseResult::order, sameIntegrator);
    const CaseTable<CaseResult> table = convergenceTable();
    table.writeCsv(folder + "/convergence.csv", results, 17);
    table.print(std::cout, results);
    RunSummary summary(kProgram, study.scene.info.name, study.scene.method.name, "several (see convergence.csv)");
    summary.addCases(results);
    for (std::size_t i = 0; i < results.size(); ++i) {
      const CaseResult& r = results[i];
      if (i + 1 == results.size() || !sameIntegrator(results[i + 1], r)) {
        summary.errors.push_back({r.integrator + "_relative_l2_finest", r.error});
        if (i > 0 && sameIntegrator(results[i - 1], r)) summary.figures.push_back({r.integrator + "_observed_order", r.order});
      }
    }
    summary.totalsFromCases();
    // The last case's step and the stable central-difference step it is a fraction of, so that a
    // one-case run (the tradeoff sweep's) reports both.
    summary.timeStep = results.back().record.timeStep;
    summary.figures.push_back({"critical_dt_last", results.back().record.stableTimeStep});
    summary.simulatedTime = study.scene.integrator.endTime;
    summary.notes.add("particles: the finest line; steps and wall time: summed over all cases");
    summary.notes.addAll(study.notes);
    summary.files.add("convergence.csv");
    summary.mergeNotesAndFiles(results);
    summary.conclude(folder, &std::cout);
    return 0;
  });
}
