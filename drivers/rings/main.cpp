// rings: two colliding rubber rings by the updated-Lagrangian SPH (Gray, Monaghan & Swift 2001;
// Monaghan 2000, "SPH without a tensile instability"). Two annuli (inner radius 0.03 m, outer
// 0.04 m; E = 1e7 Pa, nu = 0.3975, rho = 1 kg/m^3, plane strain) approach each other along x, each
// at 0.059 c0 (c0 = sqrt(K / rho0)). With the Monaghan-Gray artificial stress (epsilon = 0.3,
// n = 4) they bounce off each other and stay whole; without it the tensile instability clumps the
// particles and tears the rings apart.
//
// There is no exact solution. What the study reports instead, per case:
//   energy      the ledger (kinetic, strain, internal, viscous dissipation, artificial-stress work)
//               and the drift of the balance kinetic + internal: the "error" of the run
//   fragments   connected pieces at the end (particles closer than study.link_distance spacings
//               joined): 2 means both rings are intact, the other measured "error"
//   rebound     each ring's centre-of-mass x velocity at the end over its initial one
//   modes       the smallest pair spacing over dp and the zig-zag indicator, with the first time it
//               exceeded study.zigzag_threshold
// Cases (study.cases): artificial_stress (the scene's [method] with the artificial stress on) and
// no_artificial_stress (the same, off).
// Writes cases.csv, <case>-energy.csv, <case>-rings.csv, <case>-positions.csv, frames, summary.json.
// Results: docs/studies/sph-solids.md. Plot: /usr/bin/python3 analysis/plot_rings.py OUT.
//
//   rings --scene data/scenes/rings.toml [--set geometry.spacing=0.0005] [--out DIR]

#include "studies/rings/RingsCase.hpp"

#include "core/Error.hpp"
#include "io/run/CaseTable.hpp"
#include "io/run/DriverCommandLine.hpp"
#include "io/run/MemoryGuard.hpp"
#include "io/run/RunDriver.hpp"
#include "io/run/RunSummary.hpp"
#include "io/run/StudyCases.hpp"
#include "io/run/SceneDriver.hpp"
#include "io/scene/Format.hpp"
#include "io/scene/IntegratorSpec.hpp"
#include "io/scene/LoadScene.hpp"
#include "io/scene/ScenePath.hpp"
#include "wiring/SolidScene.hpp"
#include "wiring/UpdatedLagrangianSphSpec.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

using namespace mfwave;
using namespace mfwave::rings;

namespace {

const char* kProgram = "rings";
const std::vector<std::string> kCaseNames{"artificial_stress", "no_artificial_stress"};

SceneSchema ringsSchema() {
  using T = ValueType;
  SceneSchema schema = SceneSchema::common();
  addUpdatedLagrangianSphKeys(schema);
  useFirstOrderIntegrators(schema);
  // The rings themselves: two [[shape]] annuli and a [[region]] each with its initial velocity.
  addSolidKeys(schema);
  schema.add("study", T::Table).describedAs("the rings: what is measured");
  schema.add("study.cases", T::StringArray).defaultsTo("[\"artificial_stress\", \"no_artificial_stress\"]")
      .oneOf(kCaseNames).describedAs("runs: the scene's [method] with the artificial stress on, and off");
  schema.add("study.link_distance", T::Number).withUnit("-").defaultsTo("1.5").positive()
      .describedAs("fragments: particles closer than this many geometry.spacing are joined");
  schema.add("study.zigzag_threshold", T::Number).withUnit("-").defaultsTo("0.1").positive()
      .describedAs("report the first time the zig-zag indicator exceeds this");
  schema.add("study.snapshots", T::Integer).withUnit("-").defaultsTo("6").between(2, 100)
      .describedAs("times (evenly spaced, t = 0 and the end included) at which every particle is written to "
                   "<case>-positions.csv");
  return schema;
}

struct Plan {
  StudySettings study;
  std::vector<CaseSettings> cases;
};

// The two rings of the scene: [[shape]] annuli of equal radii centred on the x axis at
// (-offset, 0) and (offset, 0), each the solid of a [[region]] whose initial velocity is along x,
// the two opposite (each towards the other). Anything else is refused naming the key.
void readRings(SceneReader& reader, StudySettings& study) {
  const Scene& scene = study.scene;
  const SceneSolid<2> solid = readSceneSolid<2>(reader, scene);
  if (reader.count("shape") != 2 || solid.regions.size() != 2)
    reader.fail(reader.count("shape") != 2 ? "shape" : "region",
                "the rings study takes two [[shape]] annuli and a [[region]] for each (its initial velocity)");
  std::array<Vec2, 2> centre{};
  std::array<Real, 2> inner{}, outer{}, speed{};
  for (std::size_t i = 0; i < 2; ++i) {
    const std::string shape = scene::indexPath("shape", i);
    const auto key = [&](const char* k) { return scene::childPath(shape, k); };
    if (reader.string(key("type")) != "annulus") reader.fail(key("type"), "a ring is an annulus");
    const std::vector<Real> c = reader.numbers(key("centre"), 2);
    centre[i] = Vec2(c[0], c[1]);
    inner[i] = reader.number(key("inner_radius"));
    outer[i] = reader.number(key("outer_radius"));
    const std::string region = scene::indexPath("region", i);
    const std::string name = reader.string(key("name"));
    if (reader.string(scene::childPath(region, "solid")) != name)
      reader.fail(scene::childPath(region, "solid"), "region " + std::to_string(i) + " must be the ring '" + name + "'");
    const std::vector<Real>& v = solid.initialVelocity[i];
    if (v.empty() || v[1] != 0)
      reader.fail(scene::childPath(region, "initial_velocity"), "each ring moves along x: give [v, 0]");
    speed[i] = v[0];
    if (solid.materials[i + 1].lambda() != scene.material.material().lambda() ||
        solid.materials[i + 1].mu() != scene.material.material().mu() ||
        solid.materials[i + 1].density() != scene.material.material().density())
      reader.fail(scene::childPath(region, "density"), "the rings are of [material]: give the region no material");
  }
  const std::size_t left = centre[0][0] < centre[1][0] ? 0 : 1, right = 1 - left;
  if (inner[0] != inner[1] || outer[0] != outer[1])
    reader.fail("shape[1].outer_radius", "the two rings must be equal (the same inner and outer radii)");
  if (centre[0][1] != 0 || centre[1][1] != 0 || centre[left][0] != -centre[right][0] || !(centre[right][0] > outer[0]))
    reader.fail("shape[1].centre", "the rings sit at (-x, 0) and (x, 0) with x above the outer radius (apart)");
  if (!(speed[left] > 0) || speed[right] != -speed[left])
    reader.fail("region[" + std::to_string(right) + "].initial_velocity",
                "the rings approach each other at equal speeds: [v, 0] on the left one, [-v, 0] on the right");
  study.innerRadius = inner[0];
  study.outerRadius = outer[0];
  study.centreOffset = centre[right][0];
  study.approachSpeed = speed[left];
  if (study.outerRadius - study.innerRadius < 2 * scene.geometry.spacing)
    reader.fail("geometry.spacing", "leaves fewer than 2 particles across the ring wall (" +
                                        scene::formatNumber(study.outerRadius - study.innerRadius) + " m)");
  {
    // Two rings of pi (R^2 - r^2) / dp^2 particles; the UL-SPH in 2-D: 2.0 KiB per particle, with a margin.
    const Real area = 3.14159265358979 * (study.outerRadius * study.outerRadius - study.innerRadius * study.innerRadius);
    const std::string why =
        memoryRefusal("rings at dp = " + scene::formatNumber(scene.geometry.spacing),
                      {2 * area / (scene.geometry.spacing * scene.geometry.spacing), 3072, "the UL-SPH in 2-D, 2.0 KiB: 1.4 KiB measured and its pair table"});
    if (!why.empty()) reader.fail("geometry.spacing", why);
  }
  // The rings span |x| <= offset + outer_radius, |y| <= outer_radius at t = 0: inside the window.
  const GeometrySpec& g = scene.geometry;
  const Real reach[2] = {study.centreOffset + study.outerRadius, study.outerRadius};
  for (std::size_t a = 0; a < 2; ++a)
    if (g.lower[a] > -reach[a] || g.upper[a] < reach[a])
      reader.fail("geometry.upper", "the box " + g.describeBox() +
                                        " (the window of the pictures) does not hold the "
                                        "rings at t = 0: they span |x| <= " +
                                        scene::formatNumber(reach[0]) + ", |y| <= " + scene::formatNumber(reach[1]));
}

Plan readPlan(SceneReader& reader) {
  Plan plan;
  StudySettings& study = plan.study;
  study.autoPointSize = !reader.has("output.png_point_size");
  study.scene = readScene(reader);
  const Scene& scene = study.scene;
  if (scene.info.dimension != 2) reader.fail("scene.dimension", "the rings are a 2-D (plane strain) study");
  if (scene.method.name != "updated_lagrangian_sph")
    reader.fail("method.name", "rings runs the updated_lagrangian_sph method");
  if (scene.geometry.ghostLayers > 0)
    reader.fail("geometry.ghost_layers",
                "the rings are free bodies without ghost particles; the [geometry] box only "
                "frames the pictures");
  if (!scene.boundaries.empty()) reader.fail("boundary[0].type", "the rings are free bodies: no boundary conditions");
  if (!scene.loads.empty()) reader.fail("load[0].type", "the rings are free bodies: no loads");
  study.method = readUpdatedLagrangianSph(reader, scene.material.material());
  const IntegratorSpec& integrator = scene.integrator;  // first-order names (useFirstOrderIntegrators)
  // integrator.cfl is a factor on the method's own step criteria (CFL and viscous, force)
  study.integration = solidIntegrationSettings(integrator);
  readRings(reader, study);
  study.linkDistance = reader.number("study.link_distance");
  study.zigzagThreshold = reader.number("study.zigzag_threshold");
  study.snapshots = static_cast<int>(reader.integer("study.snapshots"));
  study.trackEvery = scene.output.probeEvery;

  const std::vector<std::string> names = reader.strings("study.cases");
  if (names.empty()) reader.fail("study.cases", "must name at least one case");
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (std::find(names.begin(), names.begin() + static_cast<long>(i), names[i]) !=
        names.begin() + static_cast<long>(i))
      reader.fail("study.cases", "names '" + names[i] + "' twice");
    plan.cases.push_back({names[i], names[i] == "artificial_stress", true});
  }
  return plan;
}

// cases.csv and the two terminal tables (the collision, the energy), one column each.
struct RingsTables {
  CaseTable<CaseResult> cases, energy;
};

RingsTables ringsTables(Real linkDistance, Real zigzagThreshold) {
  using R = const CaseResult&;
  RingsTables t;
  CaseTable<CaseResult>& c = t.cases;
  c.column("case", [](R r) { return r.settings.name; }, TerminalColumn("case", 22).left())
      .column("artificial_stress", [](R r) { return r.settings.artificialStress ? "true" : "false"; })
      .column("spacing [m]", [](R r) { return r.spacing; })
      .column("h [m]", [](R r) { return r.smoothingLength; })
      .column("particles", [](R r) { return r.record.particles; }, TerminalColumn("particles", 10))
      .column("left_particles", [](R r) { return r.leftParticles; })
      .column("c0 [m/s]", [](R r) { return r.soundSpeed; })
      .column("approach_speed [m/s]", [](R r) { return r.approachSpeed; })
      .column("mean_neighbours", [](R r) { return r.meanNeighbours; })
      .column("neighbour_rebuilds", [](R r) { return r.neighbourRebuilds; })
      .column("steps", [](R r) { return r.record.steps; }, TerminalColumn("steps", 8))
      .terminalOnly(TerminalColumn("wall[s]", 9).precision(3), [](R r) { return r.record.setupSeconds + r.record.loopSeconds; })
      .column("end_time [s]", [](R r) { return r.record.simulatedTime; })
      .column("first_step [s]", [](R r) { return r.firstStep; })
      .column("smallest_step [s]", [](R r) { return r.smallestStep; })
      .column("mean_step [s]", [](R r) { return r.record.timeStep; })
      .column("rhs_evaluations", [](R r) { return r.rhsEvaluations; })
      .column("setup [s]", [](R r) { return r.record.setupSeconds; })
      .column("run [s]", [](R r) { return r.record.loopSeconds; })
      .column("particle_steps_per_second", [](R r) { return r.record.particleStepsPerSecond(); },
              TerminalColumn("p-steps/s", 11).precision(3))
      .column("peak_memory [MiB]", [](R r) { return r.record.peakMemoryMiB; })
      .column("kinetic_start [J]", [](R r) { return r.initialEnergy.kinetic; })
      .column("kinetic_end [J]", [](R r) { return r.finalEnergy.kinetic; })
      .column("strain_end [J]", [](R r) { return r.finalEnergy.strain; })
      .column("internal_end [J]", [](R r) { return r.finalEnergy.internal; })
      .column("viscous_dissipation_end [J]", [](R r) { return r.finalEnergy.viscousDissipation; })
      .column("artificial_stress_work_end [J]", [](R r) { return r.finalEnergy.artificialStressWork; })
      .column("load_work_end [J]", [](R r) { return r.finalEnergy.loadWork; })
      .column("largest_balance_drift", [](R r) { return r.largestBalanceDrift; })
      .column("final_balance_drift", [](R r) { return r.finalBalanceDrift; })
      .column("largest_zigzag", [](R r) { return r.largestZigzag; })
      .column("first_zigzag_time [s]", [](R r) { return r.firstZigzagTime; })
      .column("smallest_spacing_ratio", [](R r) { return r.smallestSpacingRatio; })
      .column("final_spacing_ratio", [](R r) { return r.finalSpacingRatio; })
      .column("fragments", [](R r) { return r.fragments; }, TerminalColumn("fragments", 11))
      .column("stray_particles", [](R r) { return r.strayParticles; }, TerminalColumn("stray", 7))
      .column("largest_fragments",
              [](R r) {
                std::string sizes;
                for (std::size_t k = 0; k < r.fragmentSizes.size(); ++k)
                  sizes += (k ? " " : "") + std::to_string(r.fragmentSizes[k]);
                return sizes;
              })
      .column("links", [](R r) { return r.links; })
      .column("torn_links", [](R r) { return r.tornLinks; }, TerminalColumn("torn", 7))
      .terminalOnly(TerminalColumn("rebound L/R", 16),
                    [](R r) {
                      std::ostringstream rebound;
                      rebound << std::setprecision(3) << r.restitutionLeft << '/' << r.restitutionRight;
                      return rebound.str();
                    })
      .terminalOnly(TerminalColumn("min dx/dp", 12).precision(3), [](R r) { return r.smallestSpacingRatio; })
      .terminalOnly(TerminalColumn("max zigzag", 11).precision(3), [](R r) { return r.largestZigzag; })
      .terminalOnly(TerminalColumn("t(zigzag>" + scene::formatNumber(zigzagThreshold) + ")", 14).precision(3),
                    [](R r) { return r.firstZigzagTime >= 0 ? TableCell(r.firstZigzagTime) : TableCell("never"); })
      .column("vx_left_start [m/s]", [](R r) { return r.leftVelocityStart; })
      .column("vx_right_start [m/s]", [](R r) { return r.rightVelocityStart; })
      .column("vx_left_end [m/s]", [](R r) { return r.leftVelocityEnd; })
      .column("vx_right_end [m/s]", [](R r) { return r.rightVelocityEnd; })
      .column("restitution_left", [](R r) { return r.restitutionLeft; })
      .column("restitution_right", [](R r) { return r.restitutionRight; })
      .column("support_radius [m]", [](R r) { return r.supportRadius; })
      .column("contact_time [s]", [](R r) { return r.contactTime; })
      .column("separation_time [s]", [](R r) { return r.separationTime; })
      .column("smallest_gap [m]", [](R r) { return r.smallestGap; })
      .column("link_distance [dp]", [linkDistance](R) { return linkDistance; })
      .column("failure", [](R r) {
        std::string failure = r.failure;  // one CSV cell
        std::replace(failure.begin(), failure.end(), ',', ';');
        std::replace(failure.begin(), failure.end(), '\n', ' ');
        return failure;
      });
  t.energy.terminalOnly(TerminalColumn("case", 22).left(), [](R r) { return r.settings.name; })
      .terminalOnly(TerminalColumn("kinetic0", 11), [](R r) { return r.initialEnergy.kinetic; })
      .terminalOnly(TerminalColumn("kinetic", 11), [](R r) { return r.finalEnergy.kinetic; })
      .terminalOnly(TerminalColumn("strain", 11), [](R r) { return r.finalEnergy.strain; })
      .terminalOnly(TerminalColumn("internal", 11), [](R r) { return r.finalEnergy.internal; })
      .terminalOnly(TerminalColumn("viscous", 11), [](R r) { return r.finalEnergy.viscousDissipation; })
      .terminalOnly(TerminalColumn("art.stress", 11), [](R r) { return r.finalEnergy.artificialStressWork; })
      .terminalOnly(TerminalColumn("max drift", 12).precision(3), [](R r) { return r.largestBalanceDrift; })
      .terminalOnly(TerminalColumn("end drift", 12).precision(3), [](R r) { return r.finalBalanceDrift; });
  return t;
}

}  // namespace

int main(int argc, char** argv) {
  const SceneSchema schema = ringsSchema();
  DriverCommandLine cli(
      kProgram, "rings: two colliding rubber rings by updated-Lagrangian SPH, with and without the artificial stress",
      schema.describe());
  if (const auto exit = cli.parse(argc, argv)) return *exit;

  return runDriver(kProgram, [&]() -> int {
    SceneReader reader = loadDriverScene(cli.options(), schema);
    const Plan plan = readPlan(reader);
    reader.checkAllKeysRead();
    const std::string folder = prepareOutputFolder(cli.options(), plan.study.scene.output.folder, reader);

    const bool progress = !cli.options().quiet;
    const std::vector<CaseResult> results = runCases(
        plan.cases, [&](const CaseSettings& settings) { return runCase(plan.study, settings, folder, progress); },
        progress);
    const RingsTables tables = ringsTables(plan.study.linkDistance, plan.study.zigzagThreshold);
    tables.cases.writeCsv(folder + "/cases.csv", results, 8);
    tables.cases.print(std::cout, results);
    std::cout << "\nenergy at the end [J] (kinetic at t = 0, then at the end; drift of kinetic + internal over kinetic + "
                 "strain at t = 0)\n";
    tables.energy.print(std::cout, results);
    std::cout << '\n';

    const Scene& scene = plan.study.scene;
    const CaseResult& first = results.front();
    RunSummary summary(kProgram, scene.info.name, scene.method.name, plan.study.integration.integrator);
    summary.files.add("cases.csv");
    summary.addCases(results);
    summary.totalsFromFirstCase();
    summary.meanNeighbours = first.meanNeighbours;
    summary.simulatedTime = scene.integrator.endTime;  // the scene's, even when the first case stopped early
    // No exact solution: the errors are the energy balance and the fragments beyond the two rings.
    for (const CaseResult& r : results) {
      summary.errors.push_back({r.settings.name + "_largest_balance_drift", r.largestBalanceDrift});
      summary.errors.push_back({r.settings.name + "_extra_fragments", static_cast<Real>(r.fragments - 2)});
    }
    for (const CaseResult& r : results) {
      const std::string c = r.settings.name + "_";
      const UpdatedLagrangianSphEnergy& e = r.finalEnergy;
      summary.figures.push_back({c + "fragments", static_cast<Real>(r.fragments)});
      summary.figures.push_back({c + "stray_particles", static_cast<Real>(r.strayParticles)});
      summary.figures.push_back({c + "torn_links", static_cast<Real>(r.tornLinks)});
      summary.figures.push_back({c + "restitution_left", r.restitutionLeft});
      summary.figures.push_back({c + "restitution_right", r.restitutionRight});
      summary.figures.push_back({c + "vx_left_end [m/s]", r.leftVelocityEnd});
      summary.figures.push_back({c + "vx_right_end [m/s]", r.rightVelocityEnd});
      summary.figures.push_back({c + "contact_time [s]", r.contactTime});
      summary.figures.push_back({c + "separation_time [s]", r.separationTime});
      summary.figures.push_back({c + "smallest_spacing_ratio", r.smallestSpacingRatio});
      summary.figures.push_back({c + "largest_zigzag", r.largestZigzag});
      summary.figures.push_back({c + "first_zigzag_time [s]", r.firstZigzagTime});
      summary.figures.push_back({c + "kinetic_start [J]", r.initialEnergy.kinetic});
      summary.figures.push_back({c + "kinetic_end [J]", e.kinetic});
      summary.figures.push_back({c + "strain_end [J]", e.strain});
      summary.figures.push_back({c + "internal_end [J]", e.internal});
      summary.figures.push_back({c + "viscous_dissipation_end [J]", e.viscousDissipation});
      summary.figures.push_back({c + "artificial_stress_work_end [J]", e.artificialStressWork});
      summary.figures.push_back({c + "final_balance_drift", r.finalBalanceDrift});
      summary.figures.push_back({c + "steps", static_cast<Real>(r.record.steps)});
      summary.figures.push_back({c + "wall [s]", r.record.setupSeconds + r.record.loopSeconds});
      summary.figures.push_back({c + "particle_steps_per_second", r.record.particleStepsPerSecond()});
    }
    summary.notes.add(
        "no exact solution: the errors are the largest drift of the energy balance (kinetic + "
        "internal, over the initial kinetic + strain energy) and the fragments beyond the two "
        "rings at the end (0 = both intact)");
    summary.notes.add("particles, neighbours and mean dt of the first case (" + first.settings.name +
                      "); steps and wall time summed over " + std::to_string(results.size()) + " cases");
    summary.mergeNotesAndFiles(results);
    summary.conclude(folder, &std::cout);
    // Every case's outputs are written; a case the monitors stopped still makes the run fail
    // (exit 3), unless stability.allow_growth asked to run such a case on purpose.
    for (const CaseResult& r : results)
      if (!r.failure.empty() && !scene.stability.allowGrowth)
        throw InstabilityError("case " + r.settings.name + " was stopped: " + r.failure +
                                   " (the outputs of every case are written; stability.allow_growth = true "
                                   "reports such a case and exits 0)",
                               r.record.steps, r.record.simulatedTime, -1);
    return 0;
  });
}
