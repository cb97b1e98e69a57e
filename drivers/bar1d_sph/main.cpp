// bar1d-sph: two elastic bars meeting at x = 0 with +-v0, by the updated-Lagrangian SPH in 1-D
// (uniaxial strain, waves at c_p). The impact sends a compression front into each bar; behind the
// fronts the material rests under the stress -rho c v0 (SymmetricBarImpact). The study measures, at
// each particle spacing, the L1 errors of velocity and stress at the end time, the plateau stress
// against -rho c v0, the front position against c t, the energy balance, and the orders in dx.
// The exact fields are discontinuous, so an L1 order near 1 (fronts smeared over a few h) is what a
// consistent scheme can reach.
//
//   bar1d-sph --scene data/scenes/bar1d-sph.toml [--set 'study.spacings=[0.02,0.01]'] [--out DIR]
// Writes cases.csv, profile-<dx>.csv per spacing, frames of the scene's spacing (frame.pvd), and
// summary.json. Plot: /usr/bin/python3 analysis/plot_bar1d_sph.py OUT. Results: docs/studies/sph-solids.md.

#include "studies/bar1d_sph/BarCase.hpp"

#include "numerics/ConvergenceOrders.hpp"
#include "core/Error.hpp"
#include "io/run/CaseTable.hpp"
#include "io/run/DriverCommandLine.hpp"
#include "io/run/MemoryGuard.hpp"
#include "io/run/RunDriver.hpp"
#include "io/run/RunSummary.hpp"
#include "io/run/SceneDriver.hpp"
#include "io/scene/Format.hpp"
#include "io/scene/LoadScene.hpp"
#include "io/scene/Scene.hpp"
#include "wiring/UpdatedLagrangianSphSpec.hpp"

#include <cmath>
#include <sstream>
#include <iostream>

using namespace mfwave;
using namespace mfwave::bar1dsph;

namespace {

const char* kProgram = "bar1d-sph";

SceneSchema barSchema() {
  using T = ValueType;
  SceneSchema schema = SceneSchema::common();
  addUpdatedLagrangianSphKeys(schema);
  useFirstOrderIntegrators(schema);
  schema.add("study", T::Table).describedAs("the convergence study of bar1d-sph");
  schema.add("study.impact_speed", T::Number).withUnit("m/s").defaultsTo("0.001").positive()
      .describedAs("v0: the bar on x < 0 moves with +v0, the bar on x > 0 with -v0");
  schema.add("study.spacings", T::NumberArray).withUnit("m").defaultsToNote("[geometry.spacing]")
      .describedAs("particle spacings of the convergence cases (h scales with them)");
  schema.add("study.plateau_fraction", T::Number).withUnit("-").defaultsTo("0.5").between(0, 1, false, false)
      .describedAs("the plateau stress is the mean over |x| < plateau_fraction * c t");
  return schema;
}

Settings readSettings(SceneReader& reader, Scene& scene) {
  Settings settings;
  scene = readScene(reader);
  if (scene.info.dimension != 1) reader.fail("scene.dimension", "bar1d-sph is a 1-D study");
  if (scene.geometry.shape != "line") reader.fail("geometry.shape", "bar1d-sph needs a line");
  if (scene.method.name != "updated_lagrangian_sph") reader.fail("method.name", "bar1d-sph runs updated_lagrangian_sph");
  if (!scene.boundaries.empty()) reader.fail("boundary", "bar1d-sph has free ends and takes no boundaries");
  if (!scene.loads.empty()) reader.fail("load", "bar1d-sph takes no loads");
  settings.options = readUpdatedLagrangianSph(reader, scene.material.material());
  settings.integration = solidIntegrationSettings(scene.integrator);
  settings.halfLength = scene.geometry.upper[0];
  if (std::abs(scene.geometry.lower[0] + settings.halfLength) > 1e-12 * settings.halfLength)
    reader.fail("geometry.lower", "the bars meet at x = 0: lower must be -upper");
  settings.impactSpeed = reader.number("study.impact_speed");
  settings.plateauFraction = reader.number("study.plateau_fraction");
  settings.endTime = scene.integrator.endTime;
  const Real c = scene.material.material().pWaveSpeed();
  if (settings.endTime * c > settings.halfLength)
    reader.fail("integrator.end_time", "the fronts reach the free ends at t = L / c_p = " +
                                           std::to_string(settings.halfLength / c) + "; choose an end time before");
  settings.spacings = reader.has("study.spacings") ? reader.numbers("study.spacings")
                                                   : std::vector<Real>{scene.geometry.spacing};
  for (Real dx : settings.spacings)
    if (!(dx > 0) || dx > settings.halfLength / 4)
      reader.fail("study.spacings", "each spacing must be positive and at most a quarter of a bar");
  for (Real dx : settings.spacings) {
    // The bars span -L .. L: 2 L / dx particles; the UL-SPH: 2.0 KiB per particle (2-D), with a margin.
    const std::string why = memoryRefusal("bars at dx = " + mfwave::scene::formatNumber(dx),
                                          {2 * settings.halfLength / dx, 3072, "the UL-SPH, 2.0 KiB in 2-D: 1.4 KiB measured and its pair table"});
    if (!why.empty()) reader.fail("study.spacings", why);
  }
  settings.frameSpacing = scene.geometry.spacing;
  settings.output = scene.output;
  return settings;
}

// cases.csv and the terminal table, one column each.
CaseTable<CaseResult> casesTable() {
  using R = const CaseResult&;
  CaseTable<CaseResult> t;
  t.column("dx [m]", [](R r) { return r.dx; }, TerminalColumn("dx", 9))
      .column("particles", [](R r) { return r.record.particles; }, TerminalColumn("N", 7))
      .column("steps", [](R r) { return r.record.steps; }, TerminalColumn("steps", 8))
      .column("mean_neighbours", [](R r) { return r.meanNeighbours; })
      .column("l1_velocity", [](R r) { return r.l1Velocity; }, TerminalColumn("L1(v)", 11))
      .column("order_velocity", [](R r) { return r.orderVelocity; }, TerminalColumn("order", 7).precision(3))
      .column("l1_stress", [](R r) { return r.l1Stress; }, TerminalColumn("L1(sig)", 11))
      .column("order_stress", [](R r) { return r.orderStress; }, TerminalColumn("order", 7).precision(3))
      .column("plateau_stress_error", [](R r) { return r.plateauStressError; }, TerminalColumn("plateau", 11))
      .column("front_error_over_dx", [](R r) { return r.frontErrorOverDx; }, TerminalColumn("front/dx", 10))
      .column("balance_drift", [](R r) { return r.balanceDrift; }, TerminalColumn("drift", 11))
      .column("wall_time [s]", [](R r) { return r.record.loopSeconds; }, TerminalColumn("wall s", 9).precision(3));
  return t;
}

}  // namespace

int main(int argc, char** argv) {
  const SceneSchema schema = barSchema();
  DriverCommandLine cli(kProgram, "bar1d-sph: two bars meeting at +-v0, updated-Lagrangian SPH; errors and convergence in dx",
                        schema.describe());
  if (const auto exit = cli.parse(argc, argv)) return *exit;

  return runDriver(kProgram, [&]() -> int {
    SceneReader reader = loadDriverScene(cli.options(), schema);
    Scene scene;
    const Settings settings = readSettings(reader, scene);
    reader.checkAllKeysRead();
    const std::string folder = prepareOutputFolder(cli.options(), scene.output.folder, reader);

    std::vector<CaseResult> results = runCases(
        settings.spacings,
        [&](Real dx) { return runCase(settings, dx, folder, std::abs(dx - settings.frameSpacing) < 1e-12 * dx); },
        !cli.options().quiet);

    RunSummary summary(kProgram, scene.info.name, scene.method.name, settings.integration.integrator);
    summary.files.add("cases.csv");
    storeObservedOrders(results, &CaseResult::dx, &CaseResult::l1Velocity, &CaseResult::orderVelocity);
    storeObservedOrders(results, &CaseResult::dx, &CaseResult::l1Stress, &CaseResult::orderStress);
    const CaseTable<CaseResult> table = casesTable();
    table.writeCsv(folder + "/cases.csv", results, 10);
    table.print(std::cout, results);
    summary.addCases(results);
    summary.mergeNotesAndFiles(results);
    summary.totalsFromCases();
    summary.meanNeighbours = results.back().meanNeighbours;
    const CaseResult& finest = results.back();
    summary.timeStep = finest.record.timeStep;
    summary.simulatedTime = settings.endTime;
    summary.errors.push_back({"l1_velocity_finest", finest.l1Velocity});
    summary.errors.push_back({"l1_stress_finest", finest.l1Stress});
    summary.errors.push_back({"plateau_stress_error_finest", finest.plateauStressError});
    summary.errors.push_back({"front_error_over_dx_finest", finest.frontErrorOverDx});
    summary.figures.push_back({"balance_drift_finest", finest.balanceDrift});
    if (results.size() > 1) {
      summary.figures.push_back({"order_l1_velocity", finest.orderVelocity});
      summary.figures.push_back({"order_l1_stress", finest.orderStress});
    }
    summary.notes.add("particles: the finest case; steps and wall time summed over all cases");
    summary.notes.add("errors: relative L1 norms at the end time against SymmetricBarImpact; plateau error relative "
                      "to rho c v0; front error in particle spacings");
    summary.conclude(folder, &std::cout);
    return 0;
  });
}
