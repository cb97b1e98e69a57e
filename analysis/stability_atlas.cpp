// stability_atlas: where each method and integrator is stable, from the exact spectra of the
// methods' interior rows on periodic lattices, confirmed by runs (docs/studies/stability-atlas.md).
//
// For every linear(ised) method (lib/spectra/LatticeMethods), dimension and support (SPH kernel and
// h / dx, RK order and a / dx, RB shape a_r / dx) the tool takes the whole discrete spectrum
// (DispersionSpectrum, FFTW) and reports
//   - the most negative omega^2 / omega^2_max (below -1e-10: growing modes, no step is stable),
//   - the central-difference step limit 2 / omega_max as a Courant number c_p dt / dx,
//   - the points per wavelength for a phase error below study.accuracy (P and S along the axis,
//     and the worst of every line: P, S, axis, diagonal).
// The same at the default supports over Poisson's ratio (study.poisson_ratios; lambda from nu with
// mu = rho = 1). Every integrator's limit on one oscillator (lib/integrators/StabilityLimit) turns
// 2 / omega_max into its own step: stable step = L / omega_max.
// Confirmation: on a small periodic lattice of each method (default supports), random initial
// displacements (every mode of the lattice excited), runs at confirm.fractions of that lattice's
// exact limit with central difference, classic RK4 and Newmark beta = 1/12 (Fox-Goodwin, limit
// sqrt 6 / omega_max; implicit, so only where the lattice operator is sparse enough to factorise),
// each watched by the StabilityMonitor: a fraction below 1 must stay bounded for confirm.steps
// steps, one above 1 must be stopped.
//
//   stability_atlas [--scene data/scenes/stability-atlas.toml] [--set 'study.dimensions=[1]'] [--out DIR]
//
// Irregular clouds ([jitter], stability_atlas_jitter.cpp): the same verdicts from the whole spectrum
// of each method on periodic jittered clouds, with the lowest modes' error and quadratic consistency.
// Writes atlas.csv, poisson.csv, integrators.csv, confirmations.csv, jitter.csv, scene.resolved.toml and
// summary.json; plot with /usr/bin/python3 analysis/plot_stability_atlas.py DIR.

#include "catalogue/LatticeRows.hpp"
#include "numerics/DispersionSpectrum.hpp"
#include "integrators/StabilityLimit.hpp"
#include "numerics/InteriorStability.hpp"
#include "spectra/LatticeMethods.hpp"
#include "core/AtomicFile.hpp"
#include "core/Error.hpp"
#include "core/Material.hpp"
#include "integrators/IntegratorFactory.hpp"
#include "io/run/DriverCommandLine.hpp"
#include "io/run/RunDriver.hpp"
#include "io/run/RunSummary.hpp"
#include "io/run/SceneDriver.hpp"
#include "io/scene/LoadScene.hpp"
#include "kernels/KernelFactory.hpp"
#include "observers/StabilityMonitor.hpp"
#include "systems/LinearSecondOrderSystem.hpp"
#include "stability_atlas_jitter.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using namespace mfwave;

namespace {

const char* kProgram = "stability_atlas";

SceneSchema atlasSchema() {
  SceneSchema schema;
  schema.add("study", ValueType::Table).describedAs("the atlas (every key has a default)");
  schema.add("study.methods", ValueType::StringArray).withUnit("-")
      .defaultsTo("[\"finite_difference\", \"vwsph_published\", \"vwsph_consistent\", \"vwsph_galerkin\", \"rkcm\", "
                  "\"rbcm\", \"ulsph\", \"ulsph_corrected\"]")
      .oneOf(latticeRowChoices())
      .describedAs("interior rows by row id, or a catalogue method for all its rows (very_weak_sph: its three "
                   "variants; updated_lagrangian_sph: plain and corrected); rbcm in 1-D only");
  schema.add("study.dimensions", ValueType::NumberArray).withUnit("-").defaultsTo("[1.0, 2.0, 3.0]").between(1, 3)
      .describedAs("lattice dimensions");
  schema.add("study.cells_1d", ValueType::Integer).withUnit("-").defaultsTo("256").atLeast(16).describedAs(
      "periodic lattice nodes in 1-D (|k| dx resolution 2 pi / cells; doubled when a stencil needs it)");
  schema.add("study.cells_2d", ValueType::Integer).withUnit("-").defaultsTo("64").atLeast(16).describedAs(
      "nodes per axis in 2-D");
  schema.add("study.cells_3d", ValueType::Integer).withUnit("-").defaultsTo("24").atLeast(16).describedAs(
      "nodes per axis in 3-D");
  schema.add("study.kernels", ValueType::StringArray).withUnit("-")
      .defaultsTo("[\"cubic_spline\", \"quintic_spline\", \"wendland_c2\", \"gaussian\"]").oneOf(kernelNames())
      .describedAs("SPH kernels (very weak and updated-Lagrangian SPH)");
  schema.add("study.smoothing_length_ratios", ValueType::NumberArray).withUnit("-")
      .defaultsTo("[0.6, 0.8, 1.0, 1.2, 1.3, 1.5, 1.75, 2.0, 2.5, 3.0]").positive().describedAs("SPH h / dx");
  schema.add("study.ulsph_kernels", ValueType::StringArray).withUnit("-")
      .defaultsTo("[\"cubic_spline\", \"quintic_spline\", \"wendland_c2\"]").oneOf(kernelNames())
      .describedAs("kernels of the updated-Lagrangian SPH (its linearisation costs a right-hand side per unknown)");
  schema.add("study.ulsph_smoothing_length_ratios", ValueType::NumberArray).withUnit("-")
      .defaultsTo("[0.8, 1.0, 1.2, 1.3, 1.5, 2.0]").positive().describedAs("h / dx of the updated-Lagrangian SPH");
  schema.add("study.ulsph_dimensions", ValueType::NumberArray).withUnit("-").defaultsTo("[1.0, 2.0, 3.0]").between(1, 3)
      .describedAs("dimensions of the updated-Lagrangian SPH (3-D: 3.5 minutes, the confirmations on a 10^3 lattice most of it)");
  schema.add("study.max_support_3d", ValueType::Number).withUnit("-").defaultsTo("4.0").positive().describedAs(
      "3-D SPH points whose kernel support radius exceeds this many spacings are skipped (their lattice blocks "
      "need tens of GiB: a 3h Gaussian at h / dx = 3 ran out of 24 GiB)");
  schema.add("study.rk_orders", ValueType::NumberArray).withUnit("-").defaultsTo("[1.0, 2.0, 3.0]").between(1, 3)
      .describedAs("RK collocation basis orders");
  schema.add("study.rk_support_ratios", ValueType::NumberArray).withUnit("-")
      .defaultsTo("[1.0, 1.5, 2.0, 2.2, 2.5, 2.8, 3.0]").positive().describedAs("RK support a / dx");
  schema.add("study.rb_shape_ratios", ValueType::NumberArray).withUnit("-").defaultsTo("[1.0, 2.0, 3.0, 4.0]")
      .positive().describedAs("RB inverse-multiquadric shape a_r / dx (1-D)");
  schema.add("study.poisson_ratios", ValueType::NumberArray).withUnit("-").defaultsTo("[0.25, 0.4, 0.49, 0.499]")
      .describedAs("Poisson's ratios of the material sweep (mu = rho = 1; at the default supports)");
  schema.add("study.kernel", ValueType::String).defaultsTo("\"cubic_spline\"").oneOf(kernelNames()).describedAs(
      "SPH kernel of the Poisson sweep and the confirmations");
  schema.add("study.smoothing_length_ratio", ValueType::Number).withUnit("-").defaultsTo("1.3").positive()
      .describedAs("SPH h / dx of the Poisson sweep and the confirmations");
  schema.add("study.rk_order", ValueType::Integer).withUnit("-").defaultsTo("2").between(1, 3).describedAs(
      "RK order of the Poisson sweep and the confirmations");
  schema.add("study.rk_support_ratio", ValueType::Number).withUnit("-").defaultsTo("2.5").positive().describedAs(
      "RK a / dx of the Poisson sweep and the confirmations");
  schema.add("study.rb_shape_ratio", ValueType::Number).withUnit("-").defaultsTo("3.0").positive().describedAs(
      "RB a_r / dx of the Poisson sweep and the confirmations");
  schema.add("study.accuracy", ValueType::Number).withUnit("-").defaultsTo("0.01").positive().describedAs(
      "phase-speed error of the points-per-wavelength figures");
  schema.add("confirm", ValueType::Table).describedAs("runs that confirm the predicted limits");
  schema.add("confirm.enabled", ValueType::Boolean).defaultsTo("true").describedAs("run the confirmations");
  schema.add("confirm.fractions", ValueType::NumberArray).withUnit("-").defaultsTo("[0.98, 1.02]").positive()
      .describedAs("steps as fractions of each integrator's predicted limit");
  schema.add("confirm.steps", ValueType::Integer).withUnit("-").defaultsTo("10000").atLeast(100).describedAs(
      "steps a run below the limit must stay bounded for");
  schema.add("confirm.integrators", ValueType::StringArray).withUnit("-")
      .defaultsTo("[\"central_difference\", \"arkode:classic_rk4\", \"newmark:fox_goodwin\"]").describedAs(
          "integrators confirmed (central_difference, leapfrog, arkode:<table>, newmark:<beta> with beta < 1/4 or "
          "newmark:fox_goodwin, newmark:linear_acceleration)");
  schema.add("confirm.cells", ValueType::Integer).withUnit("-").defaultsTo("8").atLeast(4).describedAs(
      "nodes per axis of the confirmation lattices (raised to the smallest even size the stencil fits)");
  schema.add("confirm.implicit_max_nonzeros", ValueType::Integer).withUnit("-").defaultsTo("1000000").atLeast(0)
      .describedAs("an implicit integrator (newmark:<beta>) is run only on lattice operators with at most this many "
                   "nonzeros: it factorises M + beta dt^2 K, nearly dense for the 3-D UL-SPH (3.9e6: many minutes a run)");
  addJitterAtlasKeys(schema);
  schema.add("output", ValueType::Table).describedAs("where results go");
  schema.add("output.folder", ValueType::String).defaultsTo("\"out/stability-atlas\"").describedAs("output folder");
  return schema;
}

struct Settings {
  std::vector<std::string> methods, kernels, ulsphKernels, confirmIntegrators;
  std::vector<int> dimensions, rkOrders, ulsphDimensions;
  int cells[4] = {0, 256, 64, 24};
  std::vector<Real> smoothingRatios, ulsphRatios, rkSupports, rbShapes, poissonRatios, fractions;
  LatticeMethodSettings defaults;  // the Poisson sweep's and the confirmations' supports
  Real accuracy = 0.01;
  Real maxSupport3d = 4;
  bool confirm = true;
  long confirmSteps = 10000;
  int confirmCells = 8;
  long implicitMaxNonzeros = 1000000;
};

std::string num(Real x, int digits = 6) {
  std::ostringstream s;
  s << std::setprecision(digits) << x;
  return s.str();
}

bool isUpdatedLagrangian(const std::string& method) { return method.rfind("ulsph", 0) == 0; }
bool usesKernel(const std::string& method) { return method.rfind("vwsph", 0) == 0 || isUpdatedLagrangian(method); }

// One support of one method: the knob's name and value, and the settings that realise it.
struct Variant {
  std::string family;  // kernel name, "m=<order>", "rb" or "-" (finite difference)
  std::string knob;    // "h/dx", "a/dx", "a_r/dx", "-"
  Real value = 0;
  LatticeMethodSettings settings;
};

std::vector<Variant> variants(const std::string& method, const Settings& s, const LatticeMethodSettings& base) {
  std::vector<Variant> out;
  if (usesKernel(method)) {
    const bool ul = isUpdatedLagrangian(method);
    for (const std::string& kernel : ul ? s.ulsphKernels : s.kernels)
      for (Real h : ul ? s.ulsphRatios : s.smoothingRatios) {
        Variant v{kernel, "h/dx", h, base};
        v.settings.kernel = kernel;
        v.settings.smoothingLengthRatio = h;
        out.push_back(v);
      }
  } else if (method == "rkcm") {
    for (int m : s.rkOrders)
      for (Real a : s.rkSupports) {
        Variant v{"m=" + std::to_string(m), "a/dx", a, base};
        v.settings.rkOrder = m;
        v.settings.rkSupportRatio = a;
        out.push_back(v);
      }
  } else if (method == "rbcm") {
    for (Real a : s.rbShapes) {
      Variant v{"rb", "a_r/dx", a, base};
      v.settings.rbShapeRatio = a;
      out.push_back(v);
    }
  } else {
    out.push_back(Variant{"-", "-", 0, base});
  }
  return out;
}

Variant defaultVariant(const std::string& method, const LatticeMethodSettings& base) {
  if (usesKernel(method)) return {base.kernel, "h/dx", base.smoothingLengthRatio, base};
  if (method == "rkcm") return {"m=" + std::to_string(base.rkOrder), "a/dx", base.rkSupportRatio, base};
  if (method == "rbcm") return {"rb", "a_r/dx", base.rbShapeRatio, base};
  return {"-", "-", 0, base};
}

// What the atlas records of one operator.
struct Point {
  std::string status = "ok";  // "ok", "growing" or "fails: <why>"
  int cells = 0;
  Real smallestOverLargest = std::nan(""), imaginaryRatio = std::nan(""), courant = std::nan("");
  Real ppwPAxis = std::nan(""), ppwSAxis = std::nan(""), ppwWorst = std::nan("");
  Real seconds = 0;
};

Real ppw(const AccuracyResolution& r) { return r.attained ? r.pointsPerWavelength : std::nan(""); }

template <int D>
Point examine(const std::string& method, const LatticeMethodSettings& settings, int cells, Real accuracy) {
  Point p;
  const auto start = std::chrono::steady_clock::now();
  try {
    const Real dx = 1;
    const MethodLatticeStencil<D> stencil = latticeMethodStencil<D>(method, settings, dx, "study.methods");
    p.cells = periodicLatticeCells(stencil.acceleration, stencil.mass, dx, cells);
    const auto op = makePeriodicLatticeOperator<D>(stencil.acceleration, dx, p.cells, stencil.mass);
    const DispersionSpectrum<D> spectrum(op);
    const InteriorStability<D> verdict = interiorStability(spectrum, dx, p.cells);
    p.smallestOverLargest = verdict.smallestOverLargest();
    p.imaginaryRatio = verdict.largestImaginaryRatio;
    const Real cp = settings.material.pWaveSpeed();
    if (verdict.largestOmegaSquared > 0) p.courant = 2 / std::sqrt(verdict.largestOmegaSquared) * cp / dx;
    if (verdict.growing()) p.status = "growing";
    const bool scalar = op.components() == 1;
    Real worst = 0;
    bool anyMissed = false;
    for (Polarisation pol : {Polarisation::P, Polarisation::S}) {
      if (pol == Polarisation::S && (D == 1 || scalar)) continue;
      const Polarisation asked = scalar ? Polarisation::Scalar : pol;
      const Real c = pol == Polarisation::P ? cp : settings.material.sWaveSpeed();
      for (LatticeDirection direction : {LatticeDirection::Axis, LatticeDirection::Diagonal}) {
        if (D == 1 && direction == LatticeDirection::Diagonal) continue;
        const Real value = ppw(lineAccuracy(spectrumLine(spectrum, direction, asked, c), accuracy));
        if (direction == LatticeDirection::Axis) (pol == Polarisation::P ? p.ppwPAxis : p.ppwSAxis) = value;
        if (std::isnan(value)) anyMissed = true;
        else worst = std::max(worst, value);
      }
    }
    p.ppwWorst = anyMissed ? std::nan("") : worst;
  } catch (const Error& e) {
    p.status = std::string("fails: ") + e.what();
  }
  p.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return p;
}

struct Confirmation {
  std::string outcome;  // "bounded", "stopped", "not run: <why>"
  long steps = 0;
  Real growth = 0;      // largest |u| over the initial largest |u| (bounded runs), at the stop otherwise
  Real limitDt = 0, dt = 0;
};

// Runs `integrator` at `fraction` of its predicted limit on the method's small periodic lattice
// (assembled once per method), from random displacements, watched by the
// StabilityMonitor.
Confirmation confirm(LinearSecondOrderSystem& system, int components, const NamedIntegrator& integrator,
                     const IntegratorLimit& limit, Real omegaMax, Real fraction, long steps) {
  Confirmation out;
  out.limitDt = limit.omegaDtLimit / omegaMax;
  out.dt = fraction * out.limitDt;
  std::mt19937_64 random(12345);
  std::uniform_real_distribution<Real> uniform(-1, 1);
  Vector u0(system.size());
  for (Index i = 0; i < u0.size(); ++i) u0[i] = uniform(random);
  const Real initial = u0.cwiseAbs().maxCoeff();
  auto stepper = makeSecondOrderIntegrator(integrator.name, integrator.options);
  stepper->initialise(system, 0, u0, Vector::Zero(system.size()), out.dt);
  StabilityMonitorOptions watch;
  watch.components = components;
  watch.absoluteLimit = 1e6 * initial;
  StabilityMonitor monitor(watch);
  Real largest = initial;
  try {
    monitor.begin(stepper->state());
    for (long k = 1; k <= steps; ++k) {
      stepper->step();
      const StateView state = stepper->state();
      monitor.observe(state);
      largest = std::max(largest, state.displacement.cwiseAbs().maxCoeff());
      out.steps = k;
    }
    out.outcome = "bounded";
  } catch (const InstabilityError&) {
    out.outcome = "stopped";
    out.steps = stepper->stepCount();
    largest = std::max(largest, stepper->state().displacement.cwiseAbs().maxCoeff());
  }
  out.growth = largest / initial;
  return out;
}

struct Outputs {
  std::ostream& atlas;
  std::ostream& poisson;
  std::ostream& confirmations;
  RunSummary& summary;
  long points = 0, growing = 0, failed = 0, skipped = 0, confirmed = 0, contradicted = 0;
};

template <int D>
void study(const Settings& s, Outputs& out) {
  const int cells = s.cells[D];
  for (const std::string& method : s.methods) {
    if (!latticeMethodAvailable(method, D)) continue;
    if (isUpdatedLagrangian(method) &&
        std::find(s.ulsphDimensions.begin(), s.ulsphDimensions.end(), D) == s.ulsphDimensions.end())
      continue;
    // The support map (lambda = mu = rho = 1).
    for (const Variant& v : variants(method, s, s.defaults)) {
      Point p;
      const Real support = usesKernel(method) ? makeKernel(v.settings.kernel, D, v.value)->supportRadius() : 0;
      if (D == 3 && support > s.maxSupport3d)
        p.status = "skipped: support radius " + num(support, 3) + " dx above study.max_support_3d";
      else
        p = examine<D>(method, v.settings, cells, s.accuracy);
      out.atlas << D << ',' << method << ',' << v.family << ',' << v.knob << ',' << v.value << ','
                << '"' << p.status << '"' << ',' << p.cells << ',' << p.smallestOverLargest << ',' << p.imaginaryRatio
                << ',' << p.courant << ',' << p.ppwPAxis << ',' << p.ppwSAxis << ',' << p.ppwWorst << ','
                << p.seconds << '\n';
      ++out.points;
      if (p.status == "growing") ++out.growing;
      if (p.status.rfind("fails", 0) == 0) ++out.failed;
      if (p.status.rfind("skipped", 0) == 0) ++out.skipped;
    }
    std::cout << "  " << std::left << std::setw(17) << method << std::right << D << "-D: support map done\n";
    // The Poisson sweep at the default supports.
    const Variant base = defaultVariant(method, s.defaults);
    for (Real nu : s.poissonRatios) {
      LatticeMethodSettings settings = base.settings;
      settings.material = Material::fromLame(2 * nu / (1 - 2 * nu), 1, 1);
      const Point p = examine<D>(method, settings, cells, s.accuracy);
      const Real csOverCp = settings.material.sWaveSpeed() / settings.material.pWaveSpeed();
      out.poisson << D << ',' << method << ',' << base.family << ',' << base.knob << ',' << base.value << ',' << nu
                  << ",\"" << p.status << "\"," << p.smallestOverLargest << ',' << p.courant << ','
                  << p.courant * csOverCp << ',' << p.ppwPAxis << ',' << p.ppwSAxis << ',' << p.ppwWorst << '\n';
    }
    if (!s.confirm) continue;
    // Confirmations at the default supports, lambda = mu = rho = 1.
    try {
      const MethodLatticeStencil<D> stencil = latticeMethodStencil<D>(method, base.settings, 1, "study.methods");
      const int lattice = smallestPeriodicLatticeCells(stencil.acceleration, stencil.mass, 1.0, s.confirmCells);
      const auto op = makePeriodicLatticeOperator<D>(stencil.acceleration, 1.0, lattice, stencil.mass);
      const InteriorStability<D> verdict = interiorStability(DispersionSpectrum<D>(op), 1.0, lattice);
      if (verdict.growing()) {
        out.confirmations << D << ',' << method << ",-,-,-,-,-,\"not run: growing modes (" << verdict.describe()
                          << ")\"\n";
        continue;
      }
      const Real omegaMax = std::sqrt(verdict.largestOmegaSquared);
      // Consistent mass (RK, RB collocation): the explicit integrators solve with it every step.
      LinearSecondOrderSystem system = periodicLatticeSystem(op);
      const Index nonzeros = system.stiffness().nonZeros();
      for (const std::string& integrator : s.confirmIntegrators) {
        const IntegratorLimit limit = integratorLimit(integrator);
        const NamedIntegrator spec = namedIntegrator(integrator);
        if (spec.name == "newmark" && nonzeros > s.implicitMaxNonzeros) {
          out.confirmations << D << ',' << method << ',' << integrator << ',' << lattice
                            << ",-,-,-,\"not run: an implicit step on an operator of " << nonzeros
                            << " nonzeros (confirm.implicit_max_nonzeros)\"\n";
          std::cout << "    " << std::left << std::setw(21) << integrator << std::right << " not run: " << nonzeros
                    << " nonzeros\n";
          continue;
        }
        for (Real fraction : s.fractions) {
          const Confirmation c = confirm(system, op.components(), spec, limit, omegaMax, fraction, s.confirmSteps);
          const bool expected = fraction < 1 ? c.outcome == "bounded" : c.outcome == "stopped";
          ++(expected ? out.confirmed : out.contradicted);
          out.confirmations << D << ',' << method << ',' << integrator << ',' << lattice << ',' << fraction << ','
                            << c.dt << ',' << c.steps << ',' << c.outcome << ',' << c.growth << ','
                            << (expected ? "as predicted" : "CONTRADICTS the prediction") << '\n';
          std::cout << "    " << std::left << std::setw(21) << integrator << std::right << " at " << fraction
                    << " of the limit: " << c.outcome << " after " << c.steps << " steps (largest |u| "
                    << num(c.growth, 3) << " x initial)" << (expected ? "" : "  <-- CONTRADICTS the prediction")
                    << '\n';
        }
      }
    } catch (const Error& e) {
      out.confirmations << D << ',' << method << ",-,-,-,-,-,\"not run: " << e.what() << "\"\n";
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  const SceneSchema schema = atlasSchema();
  DriverCommandLine cli(kProgram,
                        "stability_atlas: the stable step and the growing modes of every method, support and "
                        "integrator from exact lattice spectra, confirmed by runs. The scene is optional.",
                        schema.describe(), false);
  if (const auto exit = cli.parse(argc, argv)) return *exit;

  return runDriver(kProgram, [&]() -> int {
    const auto& opt = cli.options();
    SceneReader reader = loadDriverScene(opt, schema);
    Settings s;
    s.methods = latticeRowsOf(reader.strings("study.methods"), "study.methods");  // catalogue names: all their rows
    s.dimensions = reader.wholeNumbers("study.dimensions");
    s.cells[1] = static_cast<int>(reader.integer("study.cells_1d"));
    s.cells[2] = static_cast<int>(reader.integer("study.cells_2d"));
    s.cells[3] = static_cast<int>(reader.integer("study.cells_3d"));
    for (int d = 1; d <= 3; ++d)
      if (s.cells[d] % 2 != 0) reader.fail("study.cells_" + std::to_string(d) + "d", "must be even");
    s.kernels = reader.strings("study.kernels");
    s.smoothingRatios = reader.numbers("study.smoothing_length_ratios");
    s.ulsphKernels = reader.strings("study.ulsph_kernels");
    s.ulsphRatios = reader.numbers("study.ulsph_smoothing_length_ratios");
    s.ulsphDimensions = reader.wholeNumbers("study.ulsph_dimensions");
    s.rkOrders = reader.wholeNumbers("study.rk_orders");
    s.rkSupports = reader.numbers("study.rk_support_ratios");
    s.rbShapes = reader.numbers("study.rb_shape_ratios");
    s.poissonRatios = reader.numbers("study.poisson_ratios");
    for (Real nu : s.poissonRatios)
      if (!(nu > -1 && nu < 0.5)) reader.fail("study.poisson_ratios", "each must lie in (-1, 0.5), got " + num(nu));
    s.defaults.kernel = reader.string("study.kernel");
    s.defaults.smoothingLengthRatio = reader.number("study.smoothing_length_ratio");
    s.defaults.rkOrder = static_cast<int>(reader.integer("study.rk_order"));
    s.defaults.rkSupportRatio = reader.number("study.rk_support_ratio");
    s.defaults.rbShapeRatio = reader.number("study.rb_shape_ratio");
    s.accuracy = reader.number("study.accuracy");
    s.maxSupport3d = reader.number("study.max_support_3d");
    s.confirm = reader.boolean("confirm.enabled");
    s.fractions = reader.numbers("confirm.fractions");
    s.confirmSteps = reader.integer("confirm.steps");
    s.confirmIntegrators = reader.strings("confirm.integrators");
    for (const std::string& integrator : s.confirmIntegrators) {
      Real limit = 0;
      try {
        limit = integratorLimit(integrator).omegaDtLimit;
      } catch (const InputError& e) {
        reader.fail("confirm.integrators", e.what());
      }
      if (std::isinf(limit))
        reader.fail("confirm.integrators", integrator + " is unconditionally stable: there is no limit to confirm "
                                           "(newmark:<beta> with beta < 1/4 has one)");
      if (!(limit > 0.5))
        reader.fail("confirm.integrators", integrator + " grows at practically any step: no limit to confirm");
    }
    s.confirmCells = static_cast<int>(reader.integer("confirm.cells"));
    s.implicitMaxNonzeros = reader.integer("confirm.implicit_max_nonzeros");
    const JitterAtlasSettings jitter = readJitterAtlasSettings(reader);
    const std::string sceneFolder = reader.string("output.folder");
    if (s.methods.empty()) reader.fail("study.methods", "needs at least one method");
    reader.checkAllKeysRead();
    const std::string folder = prepareOutputFolder(opt, sceneFolder, reader);
    const auto wallStart = std::chrono::steady_clock::now();

    AtomicFile atlasFile(folder + "/atlas.csv"), poissonFile(folder + "/poisson.csv");
    AtomicFile integratorsFile(folder + "/integrators.csv"), confirmationsFile(folder + "/confirmations.csv");
    RunSummary summary;
    Outputs out{atlasFile.stream(), poissonFile.stream(), confirmationsFile.stream(), summary};
    out.atlas << "# Interior spectra on periodic lattices (lambda = mu = rho = 1, dx = 1): omega2_min_over_max "
                 "below -1e-10 means growing modes; cd_courant = c_p dt / dx at the central-difference limit "
                 "2 / omega_max; ppw = points per wavelength for a phase error below "
              << num(s.accuracy) << " (NaN: never); status ok / growing / fails / skipped\n"
              << "dimension,method,family,knob,value,status,cells,omega2_min_over_max,imaginary_ratio,cd_courant,"
                 "ppw_p_axis,ppw_s_axis,ppw_worst,seconds\n"
              << std::setprecision(8);
    out.poisson << "# The default supports over Poisson's ratio (mu = rho = 1, lambda = 2 nu / (1 - 2 nu)): "
                   "cd_courant = c_p dt / dx and cs_courant = c_s dt / dx at the central-difference limit\n"
                << "dimension,method,family,knob,value,poisson,status,omega2_min_over_max,cd_courant,cs_courant,"
                   "ppw_p_axis,ppw_s_axis,ppw_worst\n"
                << std::setprecision(8);
    out.confirmations << "# Runs from random displacements on each method's small periodic lattice at fractions of "
                         "the predicted limit L / omega_max, watched by the StabilityMonitor (absolute limit 1e6 x "
                         "the initial amplitude); growth = largest |u| / initial\n"
                      << "dimension,method,integrator,cells,fraction,dt,steps,outcome,growth,verdict\n"
                      << std::setprecision(8);
    integratorsFile.stream() << "# The limit L of each integrator on u'' = -omega^2 u: stable for omega_max dt <= L "
                                "(inf: unconditionally); cd_fraction = L / 2, its step over central difference's\n"
                             << "integrator,omega_dt_limit,cd_fraction,growth_per_step_at_one,note\n"
                             << std::setprecision(10);
    for (const IntegratorLimit& limit : integratorLimits())
      integratorsFile.stream() << limit.integrator << ',' << limit.omegaDtLimit << ',' << limit.omegaDtLimit / 2 << ','
                               << limit.growthPerStepAtOne << ",\"" << limit.note << "\"\n";
    for (int d : s.dimensions) {
      if (d == 1) study<1>(s, out);
      else if (d == 2) study<2>(s, out);
      else study<3>(s, out);
    }
    AtomicFile jitterFile(folder + "/jitter.csv");
    const JitterAtlasCounts clouds = writeJitterAtlas(jitter, s.defaults, jitterFile.stream());
    atlasFile.commit();
    poissonFile.commit();
    jitterFile.commit();
    integratorsFile.commit();
    confirmationsFile.commit();

    summary.program = kProgram;
    summary.scene = opt.scenePath.empty() ? "(defaults)" : opt.scenePath;
    summary.method = "all linear(ised) methods (interior stencils on periodic lattices)";
    summary.integrator = "central difference, leapfrog, Newmark, ARKODE explicit tables (limits); confirmations: " +
                         std::to_string(s.confirmIntegrators.size()) + " integrators";
    summary.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
    summary.figures.push_back({"atlas_points", static_cast<Real>(out.points)});
    summary.figures.push_back({"growing_points", static_cast<Real>(out.growing)});
    summary.figures.push_back({"failed_points", static_cast<Real>(out.failed)});
    summary.figures.push_back({"skipped_points", static_cast<Real>(out.skipped)});
    summary.figures.push_back({"confirmations_as_predicted", static_cast<Real>(out.confirmed)});
    summary.figures.push_back({"confirmations_contradicting", static_cast<Real>(out.contradicted)});
    summary.figures.push_back({"jittered_clouds", static_cast<Real>(clouds.points)});
    summary.figures.push_back({"jittered_clouds_growing", static_cast<Real>(clouds.growing)});
    summary.figures.push_back({"jittered_clouds_failed", static_cast<Real>(clouds.failed)});
    summary.figures.push_back({"jittered_runs_as_predicted", static_cast<Real>(clouds.confirmed)});
    summary.figures.push_back({"jittered_runs_contradicting", static_cast<Real>(clouds.contradicted)});
    summary.files.addAll({"atlas.csv", "poisson.csv", "integrators.csv", "confirmations.csv", "jitter.csv"});
    summary.conclude(folder, opt.quiet ? nullptr : &std::cout);
    // A contradicted prediction is a defect of the analysis or of an integrator: say so by the exit.
    if (out.contradicted > 0 || clouds.contradicted > 0) {
      std::cerr << kProgram << ": " << out.contradicted + clouds.contradicted
                << " confirmation run(s) contradict the predictions (confirmations.csv, jitter.csv)\n";
      return 1;
    }
    return 0;
  });
}
