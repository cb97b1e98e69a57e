// spectra: the discrete dispersion relation omega(k) of every linear(ised) method for every
// wavenumber of a periodic lattice at once, from the FFT (FFTW) of the assembled operator's impulse
// response (lib/numerics/DispersionSpectrum.hpp), in 1, 2 and 3 D, P and S, along an axis and the
// diagonal; phase and group speed errors, points per wavelength for a phase error, anisotropy and
// the central-difference step limit of the whole spectrum. The same relation is then measured from
// simulations on the 2-D lattice (lib/numerics/SimulatedDispersion.hpp) and compared with the
// symbol plus the integrator's discrete relation. Results: docs/studies/spectra.md.
//
//   spectra [--scene data/scenes/spectra.toml] [--set 'study.dimensions=[2]'] [--out DIR]
//
// Writes spectra.csv, accuracy.csv, anisotropy.csv, simulation.csv, scene.resolved.toml and
// summary.json; plot with analysis/plot_spectra.py.

#include "catalogue/LatticeRows.hpp"
#include "numerics/DispersionSpectrum.hpp"
#include "numerics/InteriorStability.hpp"
#include "spectra/LatticeMethods.hpp"
#include "numerics/SimulatedDispersion.hpp"
#include "core/AtomicFile.hpp"
#include "core/Material.hpp"
#include "io/run/DriverCommandLine.hpp"
#include "io/run/RunDriver.hpp"
#include "io/run/RunSummary.hpp"
#include "io/run/SceneDriver.hpp"
#include "io/scene/LoadScene.hpp"
#include "kernels/KernelFactory.hpp"

#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

using namespace mfwave;

namespace {

const char* kProgram = "spectra";

SceneSchema spectraSchema() {
  SceneSchema schema;
  schema.add("study", ValueType::Table).describedAs("the spectra study (every key has a default)");
  schema.add("study.methods", ValueType::StringArray).withUnit("-")
      .defaultsTo("[\"finite_difference\", \"vwsph_published\", \"vwsph_consistent\", \"vwsph_galerkin\", \"rkcm\", "
                  "\"rbcm\", \"ulsph\", \"ulsph_corrected\"]")
      .oneOf(latticeRowChoices())
      .describedAs("interior rows by row id, or a catalogue method for all its rows (very_weak_sph: its three "
                   "variants; updated_lagrangian_sph: plain and corrected); rbcm in 1-D only: its global functions "
                   "make 2-D/3-D rows costly");
  schema.add("study.dimensions", ValueType::NumberArray).withUnit("-").defaultsTo("[1.0, 2.0, 3.0]").between(1, 3)
      .describedAs("lattice dimensions");
  schema.add("study.cells_1d", ValueType::Integer).withUnit("-").defaultsTo("512").atLeast(16).describedAs(
      "periodic lattice nodes in 1-D (the |k| dx resolution is 2 pi / cells)");
  schema.add("study.cells_2d", ValueType::Integer).withUnit("-").defaultsTo("128").atLeast(16).describedAs(
      "nodes per axis in 2-D");
  schema.add("study.cells_3d", ValueType::Integer).withUnit("-").defaultsTo("64").atLeast(16).describedAs(
      "nodes per axis in 3-D");
  schema.add("study.spacing", ValueType::Number).withUnit("m").defaultsTo("1.0").positive().describedAs(
      "lattice spacing dx (the speed ratios depend on k dx only)");
  schema.add("study.lambda", ValueType::Number).withUnit("Pa").defaultsTo("1.0").atLeast(0).describedAs("Lame lambda");
  schema.add("study.mu", ValueType::Number).withUnit("Pa").defaultsTo("1.0").positive().describedAs("shear modulus");
  schema.add("study.density", ValueType::Number).withUnit("kg/m^3").defaultsTo("1.0").positive().describedAs("density");
  schema.add("study.kernel", ValueType::String).defaultsTo("\"cubic_spline\"").oneOf(kernelNames()).describedAs(
      "SPH kernel (very weak and updated-Lagrangian SPH)");
  schema.add("study.smoothing_length_ratio", ValueType::Number).withUnit("-").defaultsTo("1.3").positive()
      .describedAs("SPH h / dx");
  schema.add("study.rk_order", ValueType::Integer).withUnit("-").defaultsTo("2").between(1, 3).describedAs(
      "RK collocation basis order");
  schema.add("study.rk_support_ratio", ValueType::Number).withUnit("-").defaultsTo("2.5").positive().describedAs(
      "RK support radius a / dx (3.0 and above: the 2-D mass symbol changes sign, explicit RKCM is unstable)");
  schema.add("study.rb_shape_ratio", ValueType::Number).withUnit("-").defaultsTo("3.0").positive().describedAs(
      "RB inverse-multiquadric shape parameter a_r / dx");
  schema.add("study.accuracy", ValueType::Number).withUnit("-").defaultsTo("0.01").positive().describedAs(
      "phase-speed error of the points-per-wavelength figure");
  schema.add("simulation", ValueType::Table).describedAs("the simulated spectra on the 2-D lattice");
  schema.add("simulation.enabled", ValueType::Boolean).defaultsTo("true").describedAs(
      "measure omega(k) from simulations of the lumped methods in 2-D");
  schema.add("simulation.cells", ValueType::Integer).withUnit("-").defaultsTo("32").atLeast(16).describedAs(
      "nodes per axis of the simulated lattice");
  schema.add("simulation.steps", ValueType::Integer).withUnit("-").defaultsTo("1024").atLeast(64).describedAs(
      "recorded steps (the time transform's length)");
  schema.add("simulation.step_fraction", ValueType::Number).withUnit("-").defaultsTo("0.7").positive().describedAs(
      "dt over the central-difference limit 2 / omega_max");
  schema.add("simulation.integrator", ValueType::String).defaultsTo("\"central_difference\"")
      .oneOf({"central_difference", "leapfrog", "newmark"}).describedAs("time integrator");
  schema.add("output", ValueType::Table).describedAs("where results go");
  schema.add("output.folder", ValueType::String).defaultsTo("\"out/spectra\"").describedAs("output folder");
  return schema;
}

struct Settings {
  std::vector<std::string> methods;
  std::vector<int> dimensions;
  int cells[4] = {0, 512, 128, 64};
  Real spacing = 1;
  LatticeMethodSettings lattice;
  Real accuracy = 0.01;
  bool simulate = true;
  int simulationCells = 32, simulationSteps = 1024;
  Real simulationFraction = 0.7;
  std::string integrator = "central_difference";
};

struct Outputs {
  std::ostream& curves;
  std::ostream& accuracy;
  std::ostream& anisotropy;
  std::ostream& simulation;
  RunSummary& summary;
  Real worstSimulationError = 0;
  long simulatedPoints = 0;
};

std::string num(Real x, int digits = 6) {
  std::ostringstream s;
  s << std::setprecision(digits) << x;
  return s.str();
}

template <int D>
void study(const Settings& s, Outputs& out) {
  const int cells = s.cells[D];
  std::vector<Polarisation> polarisations = {Polarisation::P};
  if (D > 1) polarisations.push_back(Polarisation::S);
  std::vector<LatticeDirection> directions = {LatticeDirection::Axis};
  if (D > 1) directions.push_back(LatticeDirection::Diagonal);
  for (const std::string& method : s.methods) {
    if (!latticeMethodAvailable(method, D)) {
      std::cout << "  " << method << " " << D << "-D: skipped (1-D only)\n";
      continue;
    }
    // The scalar finite difference is reported as P, the one wave it has.
    const MethodLatticeStencil<D> stencil = latticeMethodStencil<D>(method, s.lattice, s.spacing, "study.methods");
    const int lattice = periodicLatticeCells(stencil.acceleration, stencil.mass, s.spacing, cells);
    const auto start = std::chrono::steady_clock::now();
    const auto op = makePeriodicLatticeOperator<D>(stencil.acceleration, s.spacing, lattice, stencil.mass);
    const DispersionSpectrum<D> spectrum(op);
    const InteriorStability<D> verdict = interiorStability(spectrum, s.spacing, lattice);
    const Real seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const Real cp = s.lattice.material.pWaveSpeed();
    // The central-difference limit of the whole spectrum, as a Courant number c_p dt / dx.
    const Real courant = verdict.largestOmegaSquared > 0 ? 2 / std::sqrt(verdict.largestOmegaSquared) * cp / s.spacing
                                                         : std::nan("");
    const bool stable = !verdict.growing();
    if (!stable) std::cout << "  " << method << " " << D << "-D: " << verdict.describe() << '\n';
    const bool scalar = op.components() == 1;
    for (Polarisation pol : polarisations) {
      if (scalar && pol == Polarisation::S) continue;
      const Polarisation asked = scalar ? Polarisation::Scalar : pol;
      const Real c = pol == Polarisation::P ? cp : s.lattice.material.sWaveSpeed();
      std::vector<std::vector<DispersionSample>> lines;
      for (LatticeDirection direction : directions) {
        lines.push_back(spectrumLine(spectrum, direction, asked, c));
        for (const auto& sample : lines.back())
          out.curves << method << ',' << D << ',' << latticeDirectionName(direction) << ','
                     << polarisationName(pol) << ',' << sample.kdx << ',' << sample.phaseSpeedRatio << ','
                     << sample.groupSpeedRatio << ',' << sample.alignment << '\n';
        const AccuracyResolution resolution = lineAccuracy(lines.back(), s.accuracy);
        const std::string ppw = !resolution.attained ? "never" : resolution.wholeBand ? "<=2" : num(resolution.pointsPerWavelength, 4);
        out.accuracy << method << ',' << D << ',' << latticeDirectionName(direction) << ',' << polarisationName(pol)
                     << ',' << lattice << ',' << lines.back().front().kdx << ',' << lines.back().front().phaseSpeedRatio
                     << ',' << (resolution.attained ? resolution.pointsPerWavelength : std::nan("")) << ','
                     << courant << ',' << (stable ? 1 : 0) << ','
                     << verdict.smallestOverLargest() << ','
                     << verdict.largestImaginaryRatio << ',' << stencil.translationDifference << '\n';
        std::cout << "  " << std::left << std::setw(18) << method << std::right << D << "-D " << std::setw(8)
                  << latticeDirectionName(direction) << ' ' << polarisationName(pol) << ": long-wave p "
                  << std::setw(10) << num(lines.back().front().phaseSpeedRatio) << ", points per wavelength for "
                  << num(100 * s.accuracy) << " %: " << std::setw(6) << ppw << ", CD limit c dt/dx "
                  << num(courant, 4) << (stable ? "" : " (unstable: omega^2 < 0 or complex)") << "  ["
                  << lattice << "^" << D << ", " << num(seconds, 3) << " s]\n";
        if (D == 2 && direction == LatticeDirection::Axis)
          out.summary.figures.push_back({method + "_2d_" + polarisationName(pol) + "_points_per_wavelength",
                                         resolution.attained ? resolution.pointsPerWavelength : std::nan("")});
      }
      if (lines.size() == 2)
        for (const auto& a : anisotropy(lines[0], lines[1]))
          out.anisotropy << method << ',' << D << ',' << polarisationName(pol) << ',' << a.kdx << ','
                         << a.ratioMinusOne << '\n';
    }

    if (D == 2 && s.simulate && op.lumped()) {
      if (!stable) {
        std::cout << "  " << method << " 2-D simulation: skipped (the spectrum is unstable)\n";
        continue;
      }
      const auto simOp = makePeriodicLatticeOperator<D>(stencil.acceleration, s.spacing, s.simulationCells);
      const DispersionSpectrum<D> simSpectrum(simOp);
      for (LatticeDirection direction : directions) {
        SimulatedDispersionOptions options;
        options.direction = direction;
        options.integrator = s.integrator;
        options.stepFraction = s.simulationFraction;
        options.steps = s.simulationSteps;
        const SimulatedDispersionResult run = simulateDispersion<D>(simOp, simSpectrum, options);
        for (const auto& p : run.points)
          out.simulation << method << ',' << D << ',' << latticeDirectionName(direction) << ','
                         << polarisationName(p.polarisation == Polarisation::Scalar ? Polarisation::P : p.polarisation)
                         << ',' << p.kdx << ',' << p.omegaSymbol << ',' << p.omegaExpected << ',' << p.omegaMeasured
                         << ',' << p.relativeError << '\n';
        out.worstSimulationError = std::max(out.worstSimulationError, run.largestError);
        out.simulatedPoints += static_cast<long>(run.points.size());
        std::cout << "  " << std::left << std::setw(18) << method << std::right << "2-D " << std::setw(8)
                  << latticeDirectionName(direction) << " simulated (" << s.integrator << ", dt = "
                  << num(s.simulationFraction) << " of the limit, " << run.steps << " steps): " << run.points.size()
                  << " peaks, largest |measured - expected| / expected " << num(run.largestError, 3) << '\n';
      }
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  const SceneSchema schema = spectraSchema();
  DriverCommandLine cli(kProgram,
                        "spectra: dispersion relations of every method from the FFT of its impulse response on a "
                        "periodic lattice, checked against simulations. The scene is optional.",
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
    s.spacing = reader.number("study.spacing");
    const Real lambda = reader.number("study.lambda"), mu = reader.number("study.mu");
    const Real rho = reader.number("study.density");
    s.lattice.material = Material::fromLame(lambda, mu, rho);
    s.lattice.kernel = reader.string("study.kernel");
    s.lattice.smoothingLengthRatio = reader.number("study.smoothing_length_ratio");
    s.lattice.rkOrder = static_cast<int>(reader.integer("study.rk_order"));
    s.lattice.rkSupportRatio = reader.number("study.rk_support_ratio");
    s.lattice.rbShapeRatio = reader.number("study.rb_shape_ratio");
    s.accuracy = reader.number("study.accuracy");
    s.simulate = reader.boolean("simulation.enabled");
    s.simulationCells = static_cast<int>(reader.integer("simulation.cells"));
    if (s.simulationCells % 2 != 0) reader.fail("simulation.cells", "must be even");
    s.simulationSteps = static_cast<int>(reader.integer("simulation.steps"));
    s.simulationFraction = reader.number("simulation.step_fraction");
    s.integrator = reader.string("simulation.integrator");
    if (s.integrator != "newmark" && s.simulationFraction > 1)
      reader.fail("simulation.step_fraction", "must be at most 1 for " + s.integrator + " (its stability limit)");
    const std::string sceneFolder = reader.string("output.folder");
    if (s.methods.empty()) reader.fail("study.methods", "needs at least one method");
    reader.checkAllKeysRead();
    const std::string folder = prepareOutputFolder(opt, sceneFolder, reader);
    const auto wallStart = std::chrono::steady_clock::now();

    AtomicFile curvesFile(folder + "/spectra.csv"), accuracyFile(folder + "/accuracy.csv");
    AtomicFile anisotropyFile(folder + "/anisotropy.csv"), simulationFile(folder + "/simulation.csv");
    RunSummary summary;
    Outputs out{curvesFile.stream(), accuracyFile.stream(), anisotropyFile.stream(), simulationFile.stream(), summary};
    const std::string setting = "lambda = " + num(lambda) + ", mu = " + num(mu) + ", rho = " + num(rho) +
                                ", dx = " + num(s.spacing) + ", " + s.lattice.kernel + " h/dx = " + num(s.lattice.smoothingLengthRatio) +
                                ", RK m = " + std::to_string(s.lattice.rkOrder) + " a/dx = " + num(s.lattice.rkSupportRatio) +
                                ", RB a_r/dx = " + num(s.lattice.rbShapeRatio);
    out.curves << "# FFT dispersion spectra (" << setting << "); phase_speed = omega / (|k| c), group_speed = "
               << "(d omega / d|k|) / c, c = c_p for P (and the scalar finite-difference wave), c_s for S\n"
               << "method,dimension,direction,polarisation,kdx,phase_speed,group_speed,alignment\n"
               << std::setprecision(10);
    out.accuracy << "# Per line: long-wave phase speed ratio at the first sample kdx_first, points per wavelength "
                 << "for a phase error below " << num(s.accuracy) << " (NaN: never), the central-difference limit "
                 << "of the whole spectrum as c_p dt / dx, stable (omega^2 >= 0 and real everywhere), the smallest "
                 << "over the largest omega^2 and the largest |Im omega^2| / |omega^2| on the grid, and the "
                 << "translation check of the interior row\n"
                 << "method,dimension,direction,polarisation,cells,kdx_first,phase_first,ppw,cd_courant,stable,"
                    "omega2_min_over_max,imaginary_ratio,translation_check\n"
                 << std::setprecision(10);
    out.anisotropy << "# Diagonal over axis phase speed minus 1 at equal |k| dx\n"
                   << "method,dimension,polarisation,kdx,ratio_minus_one\n" << std::setprecision(10);
    out.simulation << "# Spectral peaks of 2-D simulations (" << s.integrator << ", dt = " << num(s.simulationFraction)
                   << " of 2 / omega_max, " << s.simulationSteps << " steps, " << s.simulationCells
                   << "^2 lattice): omega_expected = the integrator's discrete relation for omega_symbol\n"
                   << "method,dimension,direction,polarisation,kdx,omega_symbol,omega_expected,omega_measured,"
                      "relative_error\n"
                   << std::setprecision(12);
    std::cout << setting << "\n";
    for (int d : s.dimensions) {
      if (d == 1) study<1>(s, out);
      else if (d == 2) study<2>(s, out);
      else study<3>(s, out);
    }
    curvesFile.commit();
    accuracyFile.commit();
    anisotropyFile.commit();
    simulationFile.commit();

    summary.program = kProgram;
    summary.scene = opt.scenePath.empty() ? "(defaults)" : opt.scenePath;
    summary.method = "all linear(ised) methods (interior stencils on periodic lattices)";
    summary.integrator = s.simulate ? s.integrator + " (simulated spectra)" : "none (semi-discrete analysis)";
    summary.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
    summary.figures.push_back({"simulated_peaks", static_cast<Real>(out.simulatedPoints)});
    summary.figures.push_back({"simulation_largest_relative_error", out.worstSimulationError});
    summary.files.addAll({"spectra.csv", "accuracy.csv", "anisotropy.csv", "simulation.csv"});
    summary.conclude(folder, opt.quiet ? nullptr : &std::cout);
    return 0;
  });
}
