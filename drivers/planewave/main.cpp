// planewave: a plane P or S wave in a periodic box, for the linear methods (finite differences,
// very weak SPH published and consistent, RK collocation), against the exact solution
// u = U e cos(k . x - omega t). The operator is the method's interior row repeated on the periodic
// lattice (lib/analysis/PeriodicLattice.hpp), assembled once as a sparse matrix, so the box has no
// boundary and the error is the method's and the integrator's dispersion alone. The step is a
// fraction of the central-difference limit 2 / omega_max of the whole discrete spectrum (FFT,
// DispersionSpectrum). One of the speed-accuracy sweep's reference problems
// (docs/studies/tradeoff.md).
//
//   planewave [--scene data/scenes/planewave.toml] [--set study.cells=64] [--out DIR]

#include "analysis/DispersionSpectrum.hpp"
#include "analysis/LatticeMethods.hpp"
#include "analytic/PlaneWave.hpp"
#include "core/Error.hpp"
#include "core/Stopwatch.hpp"
#include "integrators/IntegratorFactory.hpp"
#include "integrators/IntegratorKind.hpp"
#include "integrators/StabilityLimit.hpp"
#include "io/run/CaseTable.hpp"
#include "io/run/DriverCommandLine.hpp"
#include "io/run/RunDriver.hpp"
#include "io/run/RunSummary.hpp"
#include "io/run/StudyCases.hpp"
#include "io/run/SceneDriver.hpp"
#include "io/scene/LoadScene.hpp"
#include "kernels/KernelFactory.hpp"
#include "systems/LinearSecondOrderSystem.hpp"

#include <Eigen/SparseLU>

#include <cmath>
#include <iostream>
#include <sstream>
#include <string>

using namespace mfwave;

namespace {

const char* kProgram = "planewave";

SceneSchema planeWaveSchema() {
  SceneSchema schema;
  schema.add("study", ValueType::Table).describedAs("the plane-wave study (every key has a default)");
  schema.add("study.dimension", ValueType::Integer).withUnit("-").defaultsTo("2").between(1, 3).describedAs(
      "dimension of the periodic box");
  schema.add("study.method", ValueType::String).defaultsTo("\"vwsph_consistent\"")
      .oneOf({"finite_difference", "vwsph_published", "vwsph_consistent", "rkcm"})
      .describedAs("method (rkcm has a consistent mass: newmark only)");
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
  schema.add("integrator", ValueType::Table).describedAs("time integration");
  schema.add("integrator.name", ValueType::String).defaultsTo("\"central_difference\"")
      .oneOf(secondOrderIntegratorNames()).describedAs("time integrator");
  schema.add("integrator.cfl", ValueType::Number).withUnit("-").defaultsTo("0.5").positive().describedAs(
      "step over the central-difference limit 2 / omega_max of the discrete spectrum (shortened to land on the end)");
  schema.add("output", ValueType::Table).describedAs("where results go");
  schema.add("output.folder", ValueType::String).defaultsTo("\"out/planewave\"").describedAs("output folder");
  return schema;
}

struct Settings {
  int dimension = 2;
  std::string method, integrator;
  LatticeDirection direction = LatticeDirection::Axis;
  bool shear = false;  // the S wave (polarisation "S"), else the P wave
  int cells = 32, wavelengths = 2;
  Real periods = 2, cfl = 0.5;
  LatticeMethodSettings lattice;
};

// What a run gave: its canonical record (particles, steps, dt, the limit, end time, times) and error.
struct Outcome : StudyCase {
  Real error = 0;
};

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

template <int D>
Outcome run(const Settings& s) {
  Stopwatch clock;
  const Real dx = 1.0 / s.cells;
  const MethodLatticeStencil<D> stencil = latticeMethodStencil<D>(s.method, s.lattice, dx, "study.method");
  const auto op = makePeriodicLatticeOperator<D>(stencil.acceleration, dx, s.cells, stencil.mass);
  const int c = op.components();
  if (c == 1 && s.shear) throw InputError("study.polarisation", "the scalar finite difference has no S wave");
  if (D == 1 && s.shear) throw InputError("study.polarisation", "there is no S wave in 1-D");
  if (!op.lumped() && integratorKind(s.integrator) != IntegratorKind::Newmark)
    throw InputError("integrator.name", "rkcm has a consistent mass; only newmark integrates it here");

  const auto extremes = DispersionSpectrum<D>(op).extremes();
  // omega^2 < 0 anywhere on the lattice grows at any step: stop before any work, as an instability
  // (exit 3), naming where in k it sits.
  if (!(extremes.smallestOmegaSquared >= -1e-10 * extremes.largestOmegaSquared)) {
    std::ostringstream where;
    where << (extremes.smallestAt * dx).transpose();
    throw InstabilityError("planewave: study.method " + s.method + ": the discrete spectrum has omega^2 < 0 (" +
                               std::to_string(extremes.smallestOmegaSquared / extremes.largestOmegaSquared) +
                               " of its largest value, at k dx = (" + where.str() +
                               ")): unstable at any step; see docs/studies/spectra.md",
                           0, 0, -1);
  }
  Outcome out;
  CaseRecord& record = out.record;
  record.stableTimeStep = 2 / std::sqrt(extremes.largestOmegaSquared);
  // The limit is exact here (the whole spectrum is known), so a step beyond the integrator's own
  // limit L / omega_max (integrators/StabilityLimit) is refused before any work: round-off would
  // seed the growing modes and a short run could still look accurate.
  const StepVerdict verdict = judgeStep(s.integrator, {}, std::sqrt(extremes.largestOmegaSquared),
                                        s.cfl * record.stableTimeStep);
  if (verdict.aboveLimit)
    throw InputError("integrator.cfl", std::to_string(s.cfl) + " is beyond the " + verdict.limit.integrator +
                                           " limit " + std::to_string(verdict.limit.omegaDtLimit) +
                                           " / omega_max = " + std::to_string(verdict.limitDt) +
                                           " of this spectrum (cfl <= " +
                                           std::to_string(verdict.limitDt / record.stableTimeStep) + ")");

  const Vec<D> n = latticeDirectionVector<D>(s.direction);
  const Vec<D> k = (s.direction == LatticeDirection::Axis ? 1.0 : std::sqrt(Real(D))) * 2 * kPi * s.wavelengths * n;
  Vec<D> e = n;
  if (s.shear) {
    e.setZero();
    if constexpr (D == 2) e << -n(1), n(0);
    if constexpr (D == 3) {
      if (s.direction == LatticeDirection::Axis) e(1) = 1;
      else e << 1 / std::sqrt(2.0), -1 / std::sqrt(2.0), 0;
    }
  }
  const Real speed = s.shear ? s.lattice.material.sWaveSpeed() : s.lattice.material.pWaveSpeed();
  const PlaneWave<D> wave(k, e, speed);
  record.simulatedTime = s.periods * wave.period();
  record.steps = static_cast<long>(std::ceil(record.simulatedTime / (s.cfl * record.stableTimeStep) - 1e-9));
  record.timeStep = record.simulatedTime / static_cast<Real>(record.steps);

  // Nodal values of the exact field; collocation unknowns are coefficients d with M d = u.
  const Index nodes = op.nodes();
  record.particles = nodes;
  auto nodal = [&](Real t, bool velocity) {
    Vector values(op.size());
    for (Index node = 0; node < nodes; ++node) {
      const std::array<int, D> at = latticeCoordinates<D>(node, s.cells);
      Vec<D> x;
      for (int d = 0; d < D; ++d) x(d) = at[static_cast<std::size_t>(d)] * dx;
      const Vec<D> u = velocity ? wave.velocity(x, t) : wave.displacement(x, t);
      if (c == 1)
        values(node) = u.dot(e);
      else
        values.segment<D>(node * D) = u;
    }
    return values;
  };
  SparseMatrix mass(op.size(), op.size());
  if (op.lumped())
    mass.setIdentity();
  else
    mass = periodicMatrix(op.mass, dx, s.cells);
  Vector u0 = nodal(0, false), v0 = nodal(0, true);
  if (!op.lumped()) {
    Eigen::SparseLU<SparseMatrix> lu(mass);
    if (lu.info() != Eigen::Success) throw Error("planewave: the collocation mass matrix is singular on this lattice");
    u0 = lu.solve(u0);
    v0 = lu.solve(v0);
  }
  LinearSecondOrderSystem system(mass, SparseMatrix(), -periodicMatrix(op.acceleration, dx, s.cells));
  auto integrator = makeSecondOrderIntegrator(s.integrator);
  integrator->initialise(system, 0, u0, v0, record.timeStep);
  record.setupSeconds = clock.seconds();
  clock.restart();
  // A growing field stops the run at once: every 16 steps, anything non-finite or a thousand times
  // the initial amplitude (the exact wave keeps its amplitude) is a blow-up.
  const Real limit = 1e3 * std::max<Real>(u0.cwiseAbs().maxCoeff(), 1e-300);
  for (long step = 1; step <= record.steps; ++step) {
    integrator->step();
    if (step % 16 != 0 && step != record.steps) continue;
    const Vector& d = integrator->state().displacement;
    Index worst = 0;
    const Real largest = d.cwiseAbs().maxCoeff(&worst);
    if (!std::isfinite(largest) || largest > limit)
      throw InstabilityError("planewave: the field grew to " + std::to_string(largest) + " (initial amplitude " +
                                 std::to_string(u0.cwiseAbs().maxCoeff()) + ") by step " + std::to_string(step) +
                                 ", t = " + std::to_string(integrator->time()) + ", at node " +
                                 std::to_string(worst / c) + ": the step is beyond the integrator's limit",
                             step, integrator->time(), static_cast<long>(worst / c));
  }
  record.loopSeconds = clock.seconds();
  const Vector& d = integrator->state().displacement;
  const Vector u = op.lumped() ? Vector(d) : Vector(mass * d);
  const Vector exact = nodal(record.simulatedTime, false);
  out.error = (u - exact).norm() / exact.norm();
  record.name = s.method + " " + std::to_string(s.dimension) + "-D, " + std::to_string(s.cells) + " cells, " +
                    s.integrator;
  record.errors = {{"relative_l2_u", out.error}};
  record.primaryError = "relative_l2_u";
  return out;
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
    s.method = reader.string("study.method");
    s.cells = static_cast<int>(reader.integer("study.cells"));
    if (s.cells % 2 != 0) reader.fail("study.cells", "must be even");
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
    s.integrator = reader.string("integrator.name");
    s.cfl = reader.number("integrator.cfl");
    const std::string sceneFolder = reader.string("output.folder");
    reader.checkAllKeysRead();
    const std::string folder = prepareOutputFolder(opt, sceneFolder, reader);
    const Stopwatch wall;

    Outcome out;
    if (s.dimension == 1) out = run<1>(s);
    else if (s.dimension == 2) out = run<2>(s);
    else out = run<3>(s);

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
