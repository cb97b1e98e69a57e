// plate: the oscillating cantilever plate of Gray, Monaghan and Swift (2001) by updated-Lagrangian
// SPH. A plate L x H (0.2 x 0.02, E = 2e6, nu = 0.3975, rho = 1000, plane strain) is clamped at
// x = 0 between fixed particles and starts straight with the velocity of its first bending mode,
// v_y = V_f c0 f(x) / f(L). Its tip's period is compared with the thin-plate period and the
// Timoshenko period (lib/analytic/CantileverPlate), over the resolutions of study.resolutions; the
// energy ledger of the main case covers 30 periods.
//
// Cases, each one run of the same scene:
//   ulsph_Hdp<n>_Vf<V>   at the scene's resolution n = H / geometry.spacing: V = study.velocity_factor
//                        to integrator.end_time (with frames), and V = study.small_velocity_factor
//                        to the same end time; then every other n of study.resolutions, for both
//                        velocity factors, to study.convergence_end_time
//   vwsph_Hdp<n>_Vf<V>   with study.very_weak_sph: the very weak form SPH (consistent variant) at the
//                        scene's resolution and the small velocity factor, to integrator.end_time
//   tlsph_Hdp<n>_Vf<V>   with study.total_lagrangian_sph: the total-Lagrangian SPH (reference kernels,
//                        Saint Venant-Kirchhoff, hourglass penalty, no artificial terms) at the
//                        scene's resolution for both velocity factors (the large one to
//                        integrator.end_time), and at every other resolution at the small one
//   (study.linearised_modes) the method linearised about rest at every resolution: its first
//                        bending period without amplitude, artificial terms or time integration
// The periods over the resolutions get an observed order and a Richardson limit (runs and
// linearised separately). Writes cases.csv (period, errors, energy and cost per case),
// modes.csv, <case>-tip.csv, <case>-energy.csv, frames of the main case (<case>.pvd, PNG under a
// display), summary.json, scene.resolved.toml.
// Results: docs/studies/sph-solids.md. Plot: /usr/bin/python3 analysis/plot_plate.py OUT.
//
//   plate --scene data/scenes/plate.toml [--set 'study.resolutions=[5, 7, 10, 14]'] [--out DIR]

#include "studies/plate/PlateCase.hpp"

#include "studies/plate/PlateModes.hpp"

#include "numerics/RichardsonExtrapolation.hpp"
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
#include "wiring/UpdatedLagrangianSphSpec.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>

using namespace mfwave;
using namespace mfwave::plate;

namespace {

const char* kProgram = "plate";

SceneSchema plateSchema() {
  using T = ValueType;
  SceneSchema schema = SceneSchema::common();
  addUpdatedLagrangianSphKeys(schema);
  useFirstOrderIntegrators(schema);
  schema.add("study", T::Table).describedAs("the cases of the plate study");
  schema.add("study.velocity_factor", T::Number).withUnit("-").defaultsTo("0.05").positive()
      .describedAs("V_f of the main case: the tip starts at V_f c0, c0 = sqrt(K / rho)");
  schema.add("study.small_velocity_factor", T::Number).withUnit("-").defaultsTo("0.01").nonNegative()
      .describedAs("V_f of the small-amplitude cases (and of the very weak form case); 0: none");
  schema.add("study.resolutions", T::NumberArray).withUnit("-").defaultsToNote("[H / geometry.spacing]")
      .describedAs("particles across the thickness, H / dp, of the convergence cases (whole numbers)");
  schema.add("study.convergence_end_time", T::Number).withUnit("s").defaultsTo("1.5").positive()
      .describedAs("simulated time of the short cases: small V_f, very weak form SPH, other resolutions");
  schema.add("study.convergence_large_amplitude", T::Boolean).defaultsTo("false")
      .describedAs("also run study.velocity_factor at the other resolutions (by default only the small one)");
  schema.add("study.clamp_layers", T::Integer).withUnit("-").defaultsTo("3").atLeast(1)
      .describedAs("columns of fixed particles at x < 0 that clamp the plate (at least the kernel support / dp)");
  schema.add("study.energy_every", T::Integer).withUnit("-").defaultsTo("100").atLeast(1)
      .describedAs("steps between rows of the energy ledger");
  schema.add("study.png_frames", T::Integer).withUnit("-").defaultsTo("8").nonNegative()
      .describedAs("about this many PNG pictures of the main case (with output.png); 0: none");
  schema.add("study.shear_coefficient", T::Number).withUnit("-").defaultsTo("0.8333333333333334").positive()
      .describedAs("Timoshenko shear coefficient kappa of the reference (5/6 for a rectangle)");
  schema.add("study.linearised_modes", T::Boolean).defaultsTo("true")
      .describedAs("also compute the first bending period of the updated-Lagrangian SPH linearised about rest (no "
                   "amplitude, no artificial terms, no time integration) at every resolution: seconds up to "
                   "H / dp = 10, minutes beyond");
  schema.add("study.very_weak_sph", T::Boolean).defaultsTo("true")
      .describedAs("also run the very weak form SPH (consistent variant) at the scene's resolution and small V_f");
  schema.add("study.very_weak_smoothing_length_ratio", T::Number).withUnit("-").defaultsTo("1.0").positive()
      .describedAs("h / dx of the very weak form case");
  schema.add("study.very_weak_smoothing_rate", T::Number).withUnit("1/s").defaultsTo("1.0e4").nonNegative()
      .describedAs("rate of the filter v <- v - alpha (I - S)^2 v of the very weak form case (below 1e4 it blows up)");
  schema.add("study.very_weak_cfl", T::Number).withUnit("-").defaultsTo("0.5").between(0, 1, false, true)
      .describedAs("central-difference step of the very weak form case, as a fraction of its operator's stable step");
  schema.add("study.very_weak_ghost_layers", T::Integer).withUnit("-").defaultsTo("2").nonNegative()
      .describedAs("ghost layers on every face of the very weak form case (they complete the kernel sums)");
  schema.add("study.updated_lagrangian_sph", T::Boolean).defaultsTo("true")
      .describedAs("run the updated-Lagrangian SPH cases (the main case with frames, the small V_f, the other "
                   "resolutions); false leaves the other methods' cases");
  schema.add("study.total_lagrangian_sph", T::Boolean).defaultsTo("true")
      .describedAs("also run the total-Lagrangian SPH (same particles, kernel and h) at every resolution at the small "
                   "V_f, and at the scene's resolution at study.velocity_factor to integrator.end_time");
  schema.add("study.total_lagrangian_hourglass", T::Number).withUnit("-").defaultsTo("1.0").nonNegative()
      .describedAs("the total-Lagrangian SPH's hourglass penalty, in units of Young's modulus (0: off)");
  schema.add("study.total_lagrangian_cfl", T::Number).withUnit("-").defaultsTo("0.5").between(0, 1, false, true)
      .describedAs("central-difference step of the total-Lagrangian cases, as a fraction of 2 / omega_max at rest");
  return schema;
}

struct Plan {
  PlateStudy study;
  std::vector<PlateCaseSettings> cases;
  Real linearVelocityFactor = 0;  // V_f of the convergence series over resolutions
  std::vector<Index> modeResolutions;  // H / dp of the linearised modes (empty: none)
};

const char* casePrefix(PlateMethod method) {
  switch (method) {
    case PlateMethod::VeryWeak: return "vwsph";
    case PlateMethod::TotalLagrangian: return "tlsph";
    default: return "ulsph";
  }
}

std::string caseName(const char* method, Index rows, Real velocityFactor) {
  std::ostringstream s;
  s << method << "_Hdp" << rows << "_Vf" << velocityFactor;
  return s.str();
}

// The plate from [geometry] and [[boundary]]: the box is the plate, the -x face is the clamp.
void readPlate(SceneReader& reader, PlateStudy& study) {
  const Scene& scene = study.scene;
  if (scene.info.dimension != 2) reader.fail("scene.dimension", "the plate is a 2-D (plane strain) study");
  if (scene.method.name != "updated_lagrangian_sph")
    reader.fail("method.name",
                "the plate runs the updated_lagrangian_sph method (the very weak form case is "
                "study.very_weak_sph)");
  const GeometrySpec& g = scene.geometry;
  if (g.ghostLayers > 0)
    reader.fail("geometry.ghost_layers",
                "must be 0: the plate's surfaces are free and the clamp is "
                "study.clamp_layers columns of fixed particles");
  for (std::size_t a = 0; a < g.periodic.size(); ++a)
    if (g.periodic[a]) reader.fail("geometry.periodic", "the plate has no periodic axis");
  if (std::abs(g.lower[0]) > 1e-12 * (g.upper[0] - g.lower[0]))
    reader.fail("geometry.lower", "the clamp is at x = 0: lower[0] must be 0, got " + scene::formatNumber(g.lower[0]));
  study.length = g.upper[0] - g.lower[0];
  study.thickness = g.upper[1] - g.lower[1];
  study.lowerY = g.lower[1];

  if (scene.boundaries.empty())
    reader.fail("boundary", "the plate is clamped at x = 0: give [[boundary]] faces = [\"-x\"], type = \"fixed\"");
  for (std::size_t i = 0; i < scene.boundaries.size(); ++i) {
    const BoundarySpec& b = scene.boundaries[i];
    const std::string at = "boundary[" + std::to_string(i) + "]";
    if (b.type == BoundaryType::Free) continue;
    if (b.type != BoundaryType::Fixed)
      reader.fail(at + ".type", "the plate takes only the clamp (fixed, face -x) and free faces, got '" +
                                    boundaryTypeName(b.type) + "'");
    if (b.faceMask != 1u)  // BoxFace::MinusX alone
      reader.fail(at + ".faces", "only the -x face can be fixed (the clamp at x = 0)");
  }
  if ((facesWith(scene.boundaries, BoundaryType::Fixed) & 1u) == 0)
    reader.fail("boundary", "the plate is clamped at x = 0: give [[boundary]] faces = [\"-x\"], type = \"fixed\"");
  if (!scene.loads.empty())
    reader.fail("load[0].type", "the plate takes no loads: it starts from its first mode's velocity");
  if (!scene.probes.empty())
    reader.fail("probe[0].name", "the plate records its tip itself (<case>-tip.csv); remove the [[probe]] entries");
}

Index rowsOf(SceneReader& reader, const std::string& at, Real rows, const PlateStudy& study) {
  const Real rounded = std::round(rows);
  if (!(rows >= 1) || std::abs(rows - rounded) > 1e-9 * rows)
    reader.fail(at, "particles across the thickness must be a whole number >= 1, got " + scene::formatNumber(rows));
  const Real columns = study.length / (study.thickness / rounded);
  if (rounded * (columns + static_cast<Real>(study.clampLayers)) > 1e8)
    reader.fail(at, scene::formatNumber(rounded) + " particles across would make more than 1e8 particles");
  // The UL-SPH in 2-D: 1.4 KiB per particle measured (the tradeoff sweep's largest runs) and 0.6 KiB
  // of its pair table (bench_updated_lagrangian_sph at 1e6), with a margin.
  const std::string why = memoryRefusal(
      scene::formatNumber(rounded) + " particles across",
      {rounded * (columns + static_cast<Real>(study.clampLayers)), 3072, "the UL-SPH in 2-D, 2.0 KiB: 1.4 KiB measured and its pair table"});
  if (!why.empty()) reader.fail(at, why);
  if (std::abs(columns - std::round(columns)) > 1e-6 * columns)
    reader.fail(at, "dp = H / " + scene::formatNumber(rounded) + " does not divide the length " +
                        scene::formatNumber(study.length));
  return static_cast<Index>(rounded);
}

Plan readPlan(SceneReader& reader) {
  Plan plan;
  PlateStudy& study = plan.study;
  study.scene = readScene(reader);
  const Scene& scene = study.scene;
  readPlate(reader, study);
  study.sph = readUpdatedLagrangianSph(reader, scene.material.material());
  study.stepFactor = scene.integrator.timeStep ? 1 : scene.integrator.cfl;
  study.tipEvery = scene.output.probeEvery;
  study.clampLayers = reader.integer("study.clamp_layers");
  study.energyEvery = reader.integer("study.energy_every");
  study.pngFrames = reader.integer("study.png_frames");
  study.shearCoefficient = reader.number("study.shear_coefficient");
  const Real velocityFactor = reader.number("study.velocity_factor");
  const Real smallFactor = reader.number("study.small_velocity_factor");
  const Real convergenceEnd = reader.number("study.convergence_end_time");
  const bool veryWeak = reader.boolean("study.very_weak_sph");
  const bool linearisedModes = reader.boolean("study.linearised_modes");
  study.veryWeakSmoothingLengthRatio = reader.number("study.very_weak_smoothing_length_ratio");
  study.veryWeakSmoothingRate = reader.number("study.very_weak_smoothing_rate");
  study.veryWeakCfl = reader.number("study.very_weak_cfl");
  study.veryWeakGhostLayers = reader.integer("study.very_weak_ghost_layers");
  const bool totalLagrangian = reader.boolean("study.total_lagrangian_sph");
  const bool updatedLagrangian = reader.boolean("study.updated_lagrangian_sph");
  if (!updatedLagrangian && !totalLagrangian && !veryWeak)
    reader.fail("study.updated_lagrangian_sph",
                "is false, and so are study.total_lagrangian_sph and study.very_weak_sph: no case would run");
  study.totalLagrangianHourglass = reader.number("study.total_lagrangian_hourglass");
  study.totalLagrangianCfl = reader.number("study.total_lagrangian_cfl");

  const Index mainRows = rowsOf(reader, "geometry.spacing", study.thickness / scene.geometry.spacing, study);
  // The clamp must hold every neighbour of the plate's first column: its support reaches
  // kappa h = 2 h (cubic spline) beyond x = dp / 2.
  const Real reach = 2 * study.sph.smoothingLengthRatio;
  if (static_cast<Real>(study.clampLayers) + 0.5 < reach)
    reader.fail("study.clamp_layers", std::to_string(study.clampLayers) +
                                          " columns do not cover the kernel "
                                          "support (" +
                                          scene::formatNumber(reach) + " dp) of the plate's first particles");

  std::vector<Index> others;
  const std::vector<Real> resolutions =
      reader.has("study.resolutions") ? reader.numbers("study.resolutions") : std::vector<Real>{};
  for (std::size_t i = 0; i < resolutions.size(); ++i) {
    const Index rows = rowsOf(reader, "study.resolutions[" + std::to_string(i) + "]", resolutions[i], study);
    if (rows != mainRows && std::find(others.begin(), others.end(), rows) == others.end()) others.push_back(rows);
  }
  std::sort(others.begin(), others.end());

  const Real endTime = scene.integrator.endTime;
  const bool largeConvergence = reader.boolean("study.convergence_large_amplitude");
  const bool small = smallFactor > 0 && smallFactor != velocityFactor;
  const Real linearFactor = small ? smallFactor : velocityFactor;
  plan.linearVelocityFactor = linearFactor;
  const auto add = [&](PlateMethod method, Index rows, Real vf, Real end, bool frames) {
    plan.cases.push_back({caseName(casePrefix(method), rows, vf), method, rows, vf, end, frames});
  };
  // The main case (30 periods, frames), then the short cases: the small amplitude and the very weak
  // form SPH at the scene's resolution, and the other resolutions.
  if (linearisedModes) {
    plan.modeResolutions = others;
    plan.modeResolutions.push_back(mainRows);
    std::sort(plan.modeResolutions.begin(), plan.modeResolutions.end());
  }
  if (updatedLagrangian) {
    add(PlateMethod::UpdatedLagrangian, mainRows, velocityFactor, endTime, true);
    if (small) add(PlateMethod::UpdatedLagrangian, mainRows, smallFactor, convergenceEnd, false);
  }
  if (veryWeak) add(PlateMethod::VeryWeak, mainRows, linearFactor, convergenceEnd, false);
  for (Index rows : updatedLagrangian ? others : std::vector<Index>{}) {
    add(PlateMethod::UpdatedLagrangian, rows, linearFactor, convergenceEnd, false);
    if (small && largeConvergence) add(PlateMethod::UpdatedLagrangian, rows, velocityFactor, convergenceEnd, false);
  }
  // The total-Lagrangian SPH: the main amplitude over the whole run (its energy over 30 periods),
  // then the small amplitude at every resolution.
  if (totalLagrangian) {
    add(PlateMethod::TotalLagrangian, mainRows, velocityFactor, endTime, !updatedLagrangian);  // frames if main
    if (small) add(PlateMethod::TotalLagrangian, mainRows, smallFactor, convergenceEnd, false);
    for (Index rows : others) add(PlateMethod::TotalLagrangian, rows, linearFactor, convergenceEnd, false);
  }
  return plan;
}

const char* methodName(PlateMethod method) {
  switch (method) {
    case PlateMethod::VeryWeak: return "very_weak_sph";
    case PlateMethod::TotalLagrangian: return "total_lagrangian_sph";
    default: return "updated_lagrangian_sph";
  }
}

// cases.csv and the terminal table, one column each.
CaseTable<PlateCaseResult> casesTable() {
  using R = const PlateCaseResult&;
  CaseTable<PlateCaseResult> t;
  t.column("case", [](R r) { return r.settings.name; }, TerminalColumn("case", 20).left())
      .column("method", [](R r) { return methodName(r.settings.method); })
      .column("H_over_dp", [](R r) { return r.settings.rows; }, TerminalColumn("H/dp", 6))
      .column("dp [m]", [](R r) { return r.spacing; }).column("V_f", [](R r) { return r.settings.velocityFactor; })
      .column("particles", [](R r) { return r.record.particles; }, TerminalColumn("particles", 10))
      .column("fixed_particles", [](R r) { return r.fixedParticles; })
      .column("h [m]", [](R r) { return r.smoothingLength; })
      .column("mean_neighbours", [](R r) { return r.meanNeighbours; })
      .column("neighbour_rebuilds", [](R r) { return r.neighbourRebuilds; })
      .column("steps", [](R r) { return r.record.steps; }, TerminalColumn("steps", 8))
      .column("mean_dt [s]", [](R r) { return r.record.timeStep; })
      .column("end_time [s]", [](R r) { return r.settings.endTime; })
      .column("setup [s]", [](R r) { return r.record.setupSeconds; })
      .column("run [s]", [](R r) { return r.record.loopSeconds; })
      .column("wall [s]", [](R r) { return r.record.setupSeconds + r.record.loopSeconds; }, TerminalColumn("wall[s]", 9).precision(3))
      .column("particle_steps_per_second", [](R r) { return r.record.particleStepsPerSecond(); })
      .column("period [s]", [](R r) { return r.tip.period; }, TerminalColumn("period", 10).precision(5))
      .column("half_periods", [](R r) { return r.tip.halfPeriods; })
      .column("periods_run", [](R r) { return r.periodsRun(); }, TerminalColumn("periods", 8).precision(3))
      .column("early_period [s]", [](R r) { return r.tip.earlyPeriod(PlateCaseResult::earlyPeriods); },
              TerminalColumn("early", 9))
      .terminalOnly(TerminalColumn("vs thin", 8).precision(3).titledIn(9).followedBy("%"),
                    [](R r) { return 100 * r.thinError(); })
      .terminalOnly(TerminalColumn("vs Tim.", 8).precision(3).titledIn(9).followedBy("%"),
                    [](R r) { return 100 * r.timoshenkoError(); })
      .column("shortest_period [s]", [](R r) { return r.tip.shortestPeriod(); })
      .column("longest_period [s]", [](R r) { return r.tip.longestPeriod(); })
      .column("thin_period [s]", [](R r) { return r.thinPeriod; })
      .column("timoshenko_period [s]", [](R r) { return r.timoshenkoPeriod; })
      .column("thin_error", [](R r) { return r.thinError(); })
      .column("timoshenko_error", [](R r) { return r.timoshenkoError(); })
      .column("tip_start_velocity [m/s]", [](R r) { return r.tipStartVelocity; })
      .column("first_amplitude [m]", [](R r) { return r.tip.firstAmplitude(); }, TerminalColumn("amplitude", 10))
      .column("expected_amplitude [m]", [](R r) { return r.expectedAmplitude; })
      .column("first_amplitude_ratio", [](R r) { return r.tip.firstAmplitude() / r.expectedAmplitude; },
              TerminalColumn("/ expect", 9))
      .column("last_amplitude [m]", [](R r) { return r.tip.lastAmplitude(); })
      .column("energy_drift", [](R r) { return r.energyDrift; }, TerminalColumn("drift", 10).precision(3))
      .column("viscous_fraction", [](R r) { return r.viscousFraction; })
      .column("artificial_stress_fraction", [](R r) { return r.artificialStressFraction; })
      .column("largest_zigzag", [](R r) { return r.largestZigzag; })
      .column("largest_zigzag_energy", [](R r) { return r.largestZigzagEnergy; },
              TerminalColumn("zz energy", 10).precision(3))
      .column("smallest_spacing_ratio", [](R r) { return r.smallestSpacingRatio; });
  return t;
}

// Prints and records (summary errors and figures under `prefix`) the observed order and the
// Richardson limit of a period over resolutions, when there are at least two.
void reportConvergence(const std::vector<ConvergenceSample>& samples, const std::string& what,
                       const std::string& prefix, Real timoshenko, RunSummary& summary) {
  const std::optional<RichardsonSeries> c = richardsonSeries(samples);
  if (!c) return;
  const Real error = c->limit / timoshenko - 1;
  std::cout << std::setprecision(3) << "convergence of " << what << " over " << c->resolutions
            << " resolutions: observed order ";
  if (c->observedOrder)
    std::cout << *c->observedOrder;
  else
    std::cout << (c->resolutions < 3 ? "(needs 3)" : "(not monotone)");
  std::cout << ", extrapolated (order " << c->orderUsed << ") " << std::setprecision(5) << c->limit << " s, "
            << std::setprecision(3) << 100 * error << "% from Timoshenko\n";
  summary.errors.push_back({prefix + "_extrapolated_period_error_timoshenko", error});
  summary.figures.push_back({prefix + "_extrapolated_period [s]", c->limit});
  if (c->observedOrder) summary.figures.push_back({prefix + "_period_order", *c->observedOrder});
  summary.notes.add("extrapolated period (" + prefix + "): Richardson over H / dp of " + what + ", order " +
                    (c->observedOrder ? "observed through the three finest" : "2 assumed") +
                    ", limit from the two finest");
}

// modes.csv and its terminal table.
CaseTable<PlateModesResult> modesTable(Real timoshenko) {
  using R = const PlateModesResult&;
  CaseTable<PlateModesResult> t;
  t.column("H_over_dp", [](R m) { return m.rows; }, TerminalColumn("H/dp", 8).left())
      .column("unknowns", [](R m) { return m.unknowns; }, TerminalColumn("unknowns", 10))
      .column("first_period [s]", [](R m) { return m.firstPeriod; }, TerminalColumn("1st period", 12).precision(5))
      .column("timoshenko_error", [timoshenko](R m) { return m.firstPeriod / timoshenko - 1; })
      .terminalOnly(TerminalColumn("vs Tim.", 8).precision(3).titledIn(9).followedBy("%"),
                    [timoshenko](R m) { return 100 * (m.firstPeriod / timoshenko - 1); })
      .column("second_period [s]", [](R m) { return m.secondPeriod; }, TerminalColumn("2nd period", 12).precision(5))
      .column("largest_growth_rate [1/s]", [](R m) { return m.largestGrowthRate; },
              TerminalColumn("growth", 12).precision(3))
      .column("zero_modes", [](R m) { return m.zeroModes; }, TerminalColumn("zero", 8))
      .column("seconds", [](R m) { return m.seconds; }, TerminalColumn("wall[s]", 9).precision(3));
  return t;
}

void printTable(std::ostream& out, const std::vector<PlateCaseResult>& results) {
  const PlateCaseResult& first = results.front();
  out << std::setprecision(5) << "thin-plate period " << first.thinPeriod << " s, Timoshenko period "
      << first.timoshenkoPeriod << " s\n";
  out << "period: mean over the run after the first half period; vs thin / vs Tim.: its error against the references;\n"
         "early: mean over the first "
      << PlateCaseResult::earlyPeriods
      << " periods; amplitude: first peak of the tip, / expect: over"
         " v_tip(0) T / (2 pi)\n";
  casesTable().print(out, results);
}

}  // namespace

int main(int argc, char** argv) {
  const SceneSchema schema = plateSchema();
  DriverCommandLine cli(
      kProgram,
      "plate: the Gray-Monaghan-Swift oscillating cantilever plate by updated-Lagrangian SPH, against "
      "the thin-plate and Timoshenko periods",
      schema.describe());
  if (const auto exit = cli.parse(argc, argv)) return *exit;

  return runDriver(kProgram, [&]() -> int {
    SceneReader reader = loadDriverScene(cli.options(), schema);
    const Plan plan = readPlan(reader);
    reader.checkAllKeysRead();
    const std::string folder = prepareOutputFolder(cli.options(), plan.study.scene.output.folder, reader);

    const bool progress = !cli.options().quiet;
    const std::vector<PlateCaseResult> results = runCases(
        plan.cases, [&](const PlateCaseSettings& settings) { return runPlateCase(plan.study, settings, folder, progress); },
        progress);
    casesTable().writeCsv(folder + "/cases.csv", results, 8);
    printTable(std::cout, results);

    const PlateCaseResult& main = results.front();
    const Scene& scene = plan.study.scene;
    RunSummary summary(kProgram, scene.info.name, scene.method.name, scene.integrator.name);
    summary.files.add("cases.csv");
    summary.addCases(results);
    summary.totalsFromFirstCase();
    summary.meanNeighbours = main.meanNeighbours;
    summary.figures.push_back({"thin_period [s]", main.thinPeriod});
    summary.figures.push_back({"timoshenko_period [s]", main.timoshenkoPeriod});
    for (const PlateCaseResult& r : results) {
      const std::string& c = r.settings.name;
      summary.errors.push_back({c + "_period_error_thin", r.thinError()});
      summary.errors.push_back({c + "_period_error_timoshenko", r.timoshenkoError()});
      summary.figures.push_back({c + "_period [s]", r.tip.period});
      summary.figures.push_back({c + "_periods_run", r.periodsRun()});
      summary.figures.push_back({c + "_early_period [s]", r.tip.earlyPeriod(PlateCaseResult::earlyPeriods)});
      summary.figures.push_back({c + "_shortest_period [s]", r.tip.shortestPeriod()});
      summary.figures.push_back({c + "_longest_period [s]", r.tip.longestPeriod()});
      summary.figures.push_back({c + "_first_amplitude [m]", r.tip.firstAmplitude()});
      summary.figures.push_back({c + "_first_amplitude_ratio", r.tip.firstAmplitude() / r.expectedAmplitude});
      summary.figures.push_back({c + "_last_amplitude_ratio", r.tip.lastAmplitude() / r.tip.firstAmplitude()});
      summary.figures.push_back({c + "_energy_drift", r.energyDrift});
      if (r.settings.method == PlateMethod::UpdatedLagrangian) {
        summary.figures.push_back({c + "_viscous_fraction", r.viscousFraction});
        summary.figures.push_back({c + "_largest_zigzag", r.largestZigzag});
        summary.figures.push_back({c + "_largest_zigzag_energy", r.largestZigzagEnergy});
        summary.figures.push_back({c + "_smallest_spacing_ratio", r.smallestSpacingRatio});
      }
      summary.figures.push_back({c + "_particle_steps_per_second", r.record.particleStepsPerSecond()});
      summary.figures.push_back({c + "_wall [s]", r.record.setupSeconds + r.record.loopSeconds});
    }
    for (const PlateMethod method : {PlateMethod::UpdatedLagrangian, PlateMethod::TotalLagrangian}) {
      std::vector<ConvergenceSample> runSamples;
      for (const PlateCaseResult& r : results)
        if (r.settings.method == method && r.settings.velocityFactor == plan.linearVelocityFactor &&
            std::isfinite(r.tip.period) && r.tip.period > 0)
          runSamples.push_back({1 / static_cast<Real>(r.settings.rows), r.tip.period});
      reportConvergence(runSamples,
                        std::string("the ") + methodName(method) + " V_f = " +
                            scene::formatNumber(plan.linearVelocityFactor) + " period",
                        casePrefix(method), main.timoshenkoPeriod, summary);
    }
    if (!plan.modeResolutions.empty()) {
      std::vector<PlateModesResult> modes;
      for (Index rows : plan.modeResolutions) {
        modes.push_back(linearisedPlateModes(plan.study, rows));
        if (!cli.options().quiet)
          std::cerr << "  done linearised modes at H/dp = " << rows << " (" << modes.back().unknowns << " unknowns)\n";
      }
      const CaseTable<PlateModesResult> modeTable = modesTable(main.timoshenkoPeriod);
      modeTable.writeCsv(folder + "/modes.csv", modes, 8);
      std::cout << "linearised about rest (no amplitude, no artificial terms, no time integration):\n";
      modeTable.print(std::cout, modes);
      std::vector<ConvergenceSample> modeSamples;
      for (const PlateModesResult& m : modes) {
        const std::string c = "linearised_Hdp" + std::to_string(m.rows);
        summary.figures.push_back({c + "_period [s]", m.firstPeriod});
        summary.figures.push_back({c + "_growth_rate [1/s]", m.largestGrowthRate});
        summary.errors.push_back({c + "_period_error_timoshenko", m.firstPeriod / main.timoshenkoPeriod - 1});
        if (std::isfinite(m.firstPeriod)) modeSamples.push_back({1 / static_cast<Real>(m.rows), m.firstPeriod});
      }
      reportConvergence(modeSamples, "the linearised period", "linearised", main.timoshenkoPeriod, summary);
      summary.files.add("modes.csv");
    }
    summary.notes.add("particles, neighbours and mean dt of the main case (" + main.settings.name +
                      "); steps and wall time summed over " + std::to_string(results.size()) + " cases");
    summary.notes.add("errors: measured period / reference - 1 (thin plate, Timoshenko with kappa = " +
                      scene::formatNumber(plan.study.shearCoefficient) + ")");
    summary.mergeNotesAndFiles(results);
    summary.conclude(folder, &std::cout);
    return 0;
  });
}
