// planewave: a plane P or S wave in a periodic box, for the linear methods (finite differences,
// very weak SPH published, consistent and Galerkin, RK collocation, the updated-Lagrangian SPH
// linearised about rest, the spectral elements), against the exact solution
// u = U e cos(k . x - omega t). The operator is the method's interior row repeated on the periodic
// lattice (lib/numerics/PeriodicLattice.hpp), or the spectral elements with periodic faces, so the
// box has no boundary and the error is the method's and the integrator's dispersion alone. The step
// is a fraction of the central-difference limit 2 / omega_max of the whole discrete spectrum (FFT,
// DispersionSpectrum; a power iteration for the spectral elements). One of the speed-accuracy sweep's reference problems
// (docs/studies/tradeoff.md).
//
//   planewave [--scene data/scenes/planewave.toml] [--set study.cells=64] [--out DIR]

#include "studies/planewave/PlaneWaveRun.hpp"

#include "catalogue/LatticeRows.hpp"
#include "core/Error.hpp"
#include "core/Stopwatch.hpp"
#include "integrators/IntegratorFactory.hpp"
#include "io/run/CaseTable.hpp"
#include "io/run/DriverCommandLine.hpp"
#include "io/run/MemoryGuard.hpp"
#include "io/run/RunDriver.hpp"
#include "io/run/RunSummary.hpp"
#include "io/run/SceneDriver.hpp"
#include "io/scene/LoadScene.hpp"
#include "kernels/KernelFactory.hpp"

#include <cmath>
#include <iostream>
#include <string>

using namespace mfwave;
using namespace mfwave::planewave;

namespace {

const char* kProgram = "planewave";

SceneSchema planeWaveSchema() {
  SceneSchema schema;
  schema.add("study", ValueType::Table).describedAs("the plane-wave study (every key has a default)");
  schema.add("study.dimension", ValueType::Integer).withUnit("-").defaultsTo("2").between(1, 3).describedAs(
      "dimension of the periodic box");
  // The method by the catalogue's name (lib/catalogue), its variant and options as the catalogue spells
  // them; the lattice row it stands for comes from latticeRowOf. The old row ids are refused, naming
  // the new spelling.
  schema.add("study.method", ValueType::String).defaultsTo("\"very_weak_sph\"")
      .oneOf({"finite_difference", "very_weak_sph", "reproducing_kernel", "updated_lagrangian_sph", "spectral_element",
              "vwsph_published", "vwsph_consistent", "vwsph_galerkin", "rkcm", "ulsph", "ulsph_corrected"})
      .describedAs("method, by the catalogue's name (mfwave methods): finite_difference, very_weak_sph, "
                   "reproducing_kernel (a consistent mass, which explicit integrators solve every step), "
                   "updated_lagrangian_sph (linearised about rest, viscosity off), spectral_element (GLL elements with "
                   "periodic faces)");
  schema.add("study.variant", ValueType::String).defaultsTo("\"consistent\"")
      .oneOf({"galerkin", "consistent", "published"})
      .describedAs("the very weak SPH's variant (method.variant in other scenes); other methods ignore it");
  schema.add("study.gradient_correction", ValueType::Boolean).defaultsTo("false")
      .describedAs("the UL-SPH's kernel-gradient correction (method.kernel_gradient_correction in other scenes); other "
                   "methods ignore it");
  schema.add("study.cells", ValueType::Integer).withUnit("-").defaultsTo("32").atLeast(8).describedAs(
      "lattice nodes per axis (even); dx = 1 / cells, the box is the unit cube");
  schema.add("study.wavelengths", ValueType::Integer).withUnit("-").defaultsTo("2").atLeast(1).describedAs(
      "whole wavelengths across the box along x (and along y, z on the diagonal)");
  schema.add("study.direction", ValueType::String).defaultsTo("\"axis\"").oneOf({"axis", "diagonal"})
      .describedAs("propagation along x or along the lattice diagonal");
  schema.add("study.polarisation", ValueType::String).defaultsTo("\"P\"").oneOf({"P", "S"}).describedAs(
      "P (along k) or S (normal to k; not in 1-D or for the scalar finite difference)");
  schema.add("study.periods", ValueType::Number).withUnit("-").defaultsTo("2.0").positive().describedAs(
      "simulated time in periods of the exact wave");
  schema.add("study.lambda", ValueType::Number).withUnit("Pa").defaultsTo("1.0").atLeast(0).describedAs("Lame lambda");
  schema.add("study.mu", ValueType::Number).withUnit("Pa").defaultsTo("1.0").positive().describedAs("shear modulus");
  schema.add("study.density", ValueType::Number).withUnit("kg/m^3").defaultsTo("1.0").positive().describedAs("density");
  schema.add("study.kernel", ValueType::String).defaultsTo("\"cubic_spline\"").oneOf(kernelNames()).describedAs(
      "very weak SPH kernel");
  schema.add("study.smoothing_length_ratio", ValueType::Number).withUnit("-").defaultsTo("1.3").positive()
      .describedAs("very weak SPH h / dx");
  schema.add("study.rk_order", ValueType::Integer).withUnit("-").defaultsTo("2").between(1, 3).describedAs(
      "RK collocation basis order");
  schema.add("study.rk_support_ratio", ValueType::Number).withUnit("-").defaultsTo("2.5").positive().describedAs(
      "RK support a / dx");
  schema.add("study.sem_order", ValueType::Integer).withUnit("-").defaultsTo("4").between(1, 8).describedAs(
      "spectral_element: GLL order N (elements N spacings wide; cells a multiple of 2 N)");
  schema.add("integrator", ValueType::Table).describedAs("time integration");
  schema.add("integrator.name", ValueType::String).defaultsTo("\"central_difference\"")
      .oneOf(secondOrderIntegratorNames()).describedAs("time integrator");
  schema.add("integrator.cfl", ValueType::Number).withUnit("-").defaultsTo("0.5").positive().describedAs(
      "step over the central-difference limit 2 / omega_max of the discrete spectrum (shortened to land on the end)");
  schema.add("output", ValueType::Table).describedAs("where results go");
  schema.add("output.folder", ValueType::String).defaultsTo("\"out/planewave\"").describedAs("output folder");
  return schema;
}

// planewave.csv's one line: the settings and what they gave.
struct Case {
  Settings s;
  Outcome out;
};

CaseTable<Case> planeWaveTable() {
  using R = const Case&;
  CaseTable<Case> t;
  t.column("method", [](R c) { return c.s.method; })
      .column("dimension", [](R c) { return c.s.dimension; })
      .column("cells", [](R c) { return c.s.cells; })
      .column("particles", [](R c) { return c.out.record.particles; })
      .column("direction", [](R c) { return latticeDirectionName(c.s.direction); })
      .column("polarisation", [](R c) { return c.s.shear ? "S" : "P"; })
      .column("integrator", [](R c) { return c.s.integrator; })
      .column("cfl", [](R c) { return c.s.cfl; })
      .column("dt", [](R c) { return c.out.record.timeStep; })
      .column("critical_dt", [](R c) { return c.out.record.stableTimeStep; })
      .column("steps", [](R c) { return c.out.record.steps; })
      .column("end_time", [](R c) { return c.out.record.simulatedTime; })
      .column("relative_l2_u", [](R c) { return c.out.error; })
      .column("setup_s", [](R c) { return c.out.record.setupSeconds; })
      .column("loop_s", [](R c) { return c.out.record.loopSeconds; });
  return t;
}

}  // namespace

int main(int argc, char** argv) {
  const SceneSchema schema = planeWaveSchema();
  DriverCommandLine cli(kProgram,
                        "planewave: a plane P or S wave in a periodic box by a linear method, against the exact "
                        "solution. The scene is optional.",
                        schema.describe(), false);
  if (const auto exit = cli.parse(argc, argv)) return *exit;
  return runDriver(kProgram, [&]() -> int {
    const auto& opt = cli.options();
    SceneReader reader = loadDriverScene(opt, schema);
    Settings s;
    s.dimension = static_cast<int>(reader.integer("study.dimension"));
    {
      const std::string method = reader.string("study.method");
      const std::string catalogue = catalogueSpellingOf(method);
      if (!catalogue.empty())
        reader.fail("study.method", "'" + method + "' is a lattice row id; the scene names the method by the catalogue's "
                                    "name: " + catalogue + " (study.variant, study.gradient_correction)");
      // Both are read (and checked) whatever the method, so that a scene written for one method runs
      // another by --set study.method alone; each applies to its own method only.
      const std::string variant = reader.string("study.variant");
      const bool corrected = reader.boolean("study.gradient_correction");
      s.method = latticeRowOf(method, variant, corrected, "study.method");
    }
    const long cells = reader.integer("study.cells");
    if (std::pow(static_cast<Real>(cells), s.dimension) > 1e8)
      reader.fail("study.cells", std::to_string(cells) + " per axis in " + std::to_string(s.dimension) +
                                     "-D is more than 1e8 nodes");
    s.cells = static_cast<int>(cells);
    if (s.cells % 2 != 0) reader.fail("study.cells", "must be even");
    {
      // Per node, measured in the tradeoff sweep's largest runs: RK collocation 31 KiB in 2-D and
      // 76 KiB in 3-D, every other method under 0.5 KiB; with a margin.
      const bool rk = s.method.rfind("rk", 0) == 0;
      MemoryEstimate estimate{std::pow(static_cast<Real>(cells), s.dimension),
                              rk ? (s.dimension == 3 ? 131072.0 : 49152.0) : 1024.0,
                              rk ? "RK collocation, 31 KiB (2-D) and 76 KiB (3-D) measured"
                                 : "the lattice methods, under 0.5 KiB measured"};
      const std::string why = memoryRefusal(std::to_string(cells) + " cells per axis", estimate);
      if (!why.empty()) reader.fail("study.cells", why);
    }
    s.wavelengths = static_cast<int>(reader.integer("study.wavelengths"));
    if (2 * s.wavelengths >= s.cells) reader.fail("study.wavelengths", "needs more than 2 nodes per wavelength");
    s.direction = parseLatticeDirection(reader.string("study.direction"), "study.direction");
    s.shear = reader.string("study.polarisation") == "S";  // the schema allows "P" or "S" only
    s.periods = reader.number("study.periods");
    s.lattice.material = Material::fromLame(reader.number("study.lambda"), reader.number("study.mu"),
                                    reader.number("study.density"));
    s.lattice.kernel = reader.string("study.kernel");
    s.lattice.smoothingLengthRatio = reader.number("study.smoothing_length_ratio");
    s.lattice.rkOrder = static_cast<int>(reader.integer("study.rk_order"));
    s.lattice.rkSupportRatio = reader.number("study.rk_support_ratio");
    s.semOrder = static_cast<int>(reader.integer("study.sem_order"));
    s.integrator = reader.string("integrator.name");
    s.cfl = reader.number("integrator.cfl");
    const std::string sceneFolder = reader.string("output.folder");
    reader.checkAllKeysRead();
    const std::string folder = prepareOutputFolder(opt, sceneFolder, reader);
    const Stopwatch wall;

    const Outcome out = runPlaneWave(s);

    const std::vector<Case> cases{{s, out}};
    planeWaveTable().writeCsv(folder + "/planewave.csv", cases, 10);
    if (!opt.quiet)
      std::cout << s.method << " " << s.dimension << "-D, " << s.cells << " cells, " << s.wavelengths
              << " wavelengths along the " << latticeDirectionName(s.direction) << ", " << (s.shear ? "S" : "P") << ": " << s.integrator << " at "
              << s.cfl << " of the limit (" << out.record.steps << " steps): relative L2 error of u " << out.error << '\n';

    RunSummary summary(kProgram, opt.scenePath.empty() ? "(defaults)" : opt.scenePath, s.method, s.integrator);
    summary.particles = out.record.particles;
    summary.steps = out.record.steps;
    summary.timeStep = out.record.timeStep;
    summary.simulatedTime = out.record.simulatedTime;
    summary.wallSeconds = wall.seconds();
    summary.addCase(out.record);
    summary.errors.push_back({"relative_l2_u", out.error});
    summary.figures.push_back({"critical_dt", out.record.stableTimeStep});
    summary.figures.push_back({"time_step", out.record.timeStep});
    summary.figures.push_back({"loop_seconds", out.record.loopSeconds});
    summary.files.add("planewave.csv");
    summary.conclude(folder, opt.quiet ? nullptr : &std::cout);
    return 0;
  });
}
