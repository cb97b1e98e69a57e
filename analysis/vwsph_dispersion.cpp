// vwsph_dispersion: discrete dispersion of the very weak form SPH (Ding-Long-Wu) on a regular
// lattice, from the interior stencil of the assembled system (numerics/LatticeDispersion.hpp):
// normalised phase speed omega / (|k| c) and group speed (d omega / d|k|) / c of the P and S
// branches along a lattice axis and the lattice diagonal, for the published scheme, the published
// row with its row sum corrected, and the consistent variant (when the method has it), at each
// smoothing length ratio h / dx. Also the long-wave limit (the frequency gap omega(k -> 0) of a
// row that is not translation exact, the long-wave speed) and the points per wavelength for a
// phase error below study.accuracy. Results: docs/studies/vwsph-dispersion.md.
//
//   vwsph_dispersion [--scene FILE] [--set 'study.smoothing_length_ratios=[1.0, 1.5]'] [--out DIR]
//
// The scene is optional: every key has a default. Writes vwsph_dispersion.csv (the curves),
// vwsph_long_wave.csv (the long-wave table), scene.resolved.toml and summary.json; plot with
//   /usr/bin/python3 analysis/plot_vwsph_dispersion.py DIR

#include "numerics/LatticeDispersion.hpp"
#include "spectra/VeryWeakSphDispersion.hpp"
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

const char* kProgram = "vwsph_dispersion";

SceneSchema vwsphDispersionSchema() {
  SceneSchema schema;
  schema.add("study", ValueType::Table).describedAs("the lattice dispersion study (every key has a default)");
  schema.add("study.dimension", ValueType::Integer).withUnit("-").defaultsTo("3").between(1, 3).describedAs(
      "dimension of the lattice (1-D has the P branch only)");
  schema.add("study.variants", ValueType::StringArray).defaultsTo("[\"published\", \"published_row_sum\", \"consistent\"]")
      .oneOf(veryWeakSphDispersionVariantNames()).describedAs(
          "published; published_row_sum (its self block corrected so the row sums to zero); consistent "
          "(skipped with a note when the method does not have it)");
  schema.add("study.kernel", ValueType::String).defaultsTo("\"cubic_spline\"").oneOf(kernelNames()).describedAs(
      "SPH kernel");
  schema.add("study.smoothing_length_ratios", ValueType::NumberArray).withUnit("-").defaultsTo("[1.0]").positive()
      .describedAs("smoothing length h over the lattice spacing dx");
  schema.add("study.spacing", ValueType::Number).withUnit("m").defaultsTo("1.0").positive().describedAs(
      "lattice spacing dx (speed ratios depend on k dx only)");
  schema.add("study.lambda", ValueType::Number).withUnit("Pa").defaultsTo("1.0").positive().describedAs(
      "Lame constant lambda");
  schema.add("study.mu", ValueType::Number).withUnit("Pa").defaultsTo("1.0").positive().describedAs("shear modulus mu");
  schema.add("study.density", ValueType::Number).withUnit("kg/m^3").defaultsTo("1.0").positive().describedAs(
      "density rho");
  schema.add("study.kdx_min", ValueType::Number).withUnit("-").defaultsTo("0.01").positive().describedAs(
      "smallest |k| dx of the curves");
  schema.add("study.kdx_max", ValueType::Number).withUnit("-").defaultsTo("3.141592653589793").positive().describedAs(
      "largest |k| dx of the curves (pi: the axis Nyquist wavenumber)");
  schema.add("study.points", ValueType::Integer).withUnit("-").defaultsTo("315").atLeast(2).describedAs(
      "samples of |k| dx per curve");
  schema.add("study.accuracy", ValueType::Number).withUnit("-").defaultsTo("0.01").positive().describedAs(
      "phase-speed error tolerance of the points-per-wavelength figure");
  schema.add("output", ValueType::Table).describedAs("where results go");
  schema.add("output.folder", ValueType::String).defaultsTo("\"out/vwsph_dispersion\"").describedAs("output folder");
  return schema;
}

struct Settings {
  std::vector<VeryWeakSphDispersionVariant> variants;
  std::string kernel;
  std::vector<Real> ratios;
  Real spacing = 1;
  Material material = Material::fromLame(1, 1, 1);
  Real kdxMin = 0.01, kdxMax = kPi;
  int points = 315;
  Real accuracy = 0.01;
  bool quiet = false;
};

struct Tally {
  long curves = 0;
  Index particles = 0;
  Real worstTranslation = 0;
  Real worstAsymmetry = 0;
};

std::string num(Real x, int digits = 6) {
  std::ostringstream s;
  s << std::setprecision(digits) << x;
  return s.str();
}

template <int D>
void study(const Settings& settings, std::ostream& curves, std::ostream& longWave, RunSummary& summary, Tally& tally) {
  struct Direction {
    const char* name;
    Vec<D> n;
  };
  std::vector<Direction> directions = {{"axis", latticeAxis<D>()}};
  if (D > 1) directions.push_back({"diagonal", latticeDiagonal<D>()});
  std::vector<Polarisation> polarisations = {Polarisation::P};
  if (D > 1) polarisations.push_back(Polarisation::S);
  const Real cp = settings.material.pWaveSpeed(), cs = settings.material.sWaveSpeed();
  const Real dx = settings.spacing;

  std::cout << std::left << std::setw(18) << "variant" << std::right << std::setw(6) << "h/dx" << std::setw(10)
            << "direction" << std::setw(4) << "pol" << std::setw(13) << "gap [1/s]" << std::setw(13) << "c_long/c"
            << std::setw(11) << "p(pi/4)" << std::setw(11) << "p(pi/2)" << std::setw(12) << "ppw(acc)" << '\n';
  for (const Real ratio : settings.ratios)
    for (const auto variant : settings.variants) {
      const auto lattice =
          veryWeakSphInteriorStencil<D>(variant, settings.kernel, ratio, settings.material, settings.spacing);
      const char* variantName = veryWeakSphDispersionVariantName(variant);
      tally.particles = std::max(tally.particles, lattice.physicalParticles);
      tally.worstTranslation = std::max(tally.worstTranslation, lattice.translationDifference);
      const Real rowSum = lattice.stencil.rowSum()(0, 0) * dx * dx;  // sum_b G_b, (0, 0) entry, times dx^2
      if (!settings.quiet)
        std::cerr << "  " << variantName << " h/dx = " << ratio << ": " << lattice.physicalParticles << " + "
                  << lattice.ghostParticles << " ghost particles, stencil of " << lattice.stencil.size()
                  << " blocks, row sum " << num(rowSum) << " / dx^2 (times rho), translation check "
                  << num(lattice.translationDifference, 3) << '\n';
      if (lattice.translationDifference > 1e-10)
        summary.notes.add(std::string(variantName) + " h/dx = " + num(ratio) +
                          ": the centre row differs from its neighbour's by " +
                          num(lattice.translationDifference, 3) + " (not interior?)");
      for (const auto& direction : directions)
        for (const Polarisation polarisation : polarisations) {
          const Real c = polarisation == Polarisation::P ? cp : cs;
          const auto curve = dispersionCurve(lattice.stencil, direction.n, polarisation, c, dx, settings.kdxMin,
                                             settings.kdxMax, settings.points);
          for (const auto& s : curve)
            curves << variantName << ',' << ratio << ',' << direction.name << ',' << polarisationName(polarisation)
                   << ',' << s.kdx << ',' << s.kdx * ratio << ',' << s.phaseSpeedRatio << ',' << s.groupSpeedRatio
                   << ',' << s.alignment << '\n';
          ++tally.curves;
          for (const auto kdx : {0.5, kPi / 2})
            tally.worstAsymmetry = std::max(
                tally.worstAsymmetry, stencilSymbol(lattice.stencil, Vec<D>(kdx / dx * direction.n)).asymmetryRatio);
          const LongWaveLimit limit = longWaveLimit(lattice.stencil, direction.n, polarisation);
          const AccuracyResolution resolution = pointsPerWavelength(
              lattice.stencil, direction.n, polarisation, c, dx, settings.accuracy, 1e-3, kPi, 4000);
          const Real pQuarter = latticeMode(lattice.stencil, direction.n, kPi / 4 / dx, polarisation).phaseSpeed / c;
          const Real pHalf = latticeMode(lattice.stencil, direction.n, kPi / 2 / dx, polarisation).phaseSpeed / c;
          longWave << variantName << ',' << ratio << ',' << direction.name << ',' << polarisationName(polarisation)
                   << ',' << limit.gap << ',' << limit.gap * dx / c << ',' << limit.speed / c << ',' << pQuarter << ','
                   << pHalf << ',' << (resolution.attained ? resolution.kdx : std::nan("")) << ','
                   << (resolution.attained ? resolution.pointsPerWavelength : std::nan("")) << ','
                   << (resolution.wholeBand ? 1 : 0) << '\n';
          std::string ppw = resolution.attained ? num(resolution.pointsPerWavelength, 4) : "never";
          if (resolution.wholeBand) ppw = "<= 2";
          std::cout << std::left << std::setw(18) << variantName << std::right << std::setw(6) << ratio
                    << std::setw(10) << direction.name << std::setw(4) << polarisationName(polarisation)
                    << std::setw(13) << num(limit.gap) << std::setw(13) << num(limit.speed / c, 8)
                    << std::setw(11) << num(pQuarter) << std::setw(11) << num(pHalf) << std::setw(12) << ppw << '\n';
          if (variant != VeryWeakSphDispersionVariant::PublishedRowSumCorrected && ratio == settings.ratios.front()) {
            const std::string key = std::string(variantName) + "_" + direction.name + "_" +
                                    polarisationName(polarisation);
            summary.figures.push_back({key + "_long_wave_speed_ratio", limit.speed / c});
            summary.figures.push_back({key + "_gap_dx_over_c", limit.gap * dx / c});
          }
        }
    }
}

}  // namespace

int main(int argc, char** argv) {
  const SceneSchema schema = vwsphDispersionSchema();
  DriverCommandLine cli(kProgram,
                        "vwsph_dispersion: phase and group speed errors of the very weak form SPH's interior stencil "
                        "on a lattice against k dx, P and S, along an axis and the diagonal. The scene is optional.",
                        schema.describe(), false);
  if (const auto exit = cli.parse(argc, argv)) return *exit;

  return runDriver(kProgram, [&]() -> int {
    const auto& opt = cli.options();
    SceneReader reader = loadDriverScene(opt, schema);
    Settings settings;
    const int dimension = static_cast<int>(reader.integer("study.dimension"));
    const auto variantNames = reader.strings("study.variants");
    settings.kernel = reader.string("study.kernel");
    settings.ratios = reader.numbers("study.smoothing_length_ratios");
    settings.spacing = reader.number("study.spacing");
    const Real lambda = reader.number("study.lambda"), mu = reader.number("study.mu");
    const Real rho = reader.number("study.density");
    settings.kdxMin = reader.number("study.kdx_min");
    settings.kdxMax = reader.number("study.kdx_max");
    settings.points = static_cast<int>(reader.integer("study.points"));
    settings.accuracy = reader.number("study.accuracy");
    const std::string sceneFolder = reader.string("output.folder");  // read always: --out overrides it
    if (settings.kdxMax <= settings.kdxMin) reader.fail("study.kdx_max", "must exceed study.kdx_min");
    if (settings.ratios.empty()) reader.fail("study.smoothing_length_ratios", "needs at least one ratio");
    settings.material = Material::fromLame(lambda, mu, rho);
    settings.quiet = opt.quiet;
    RunSummary summary;
    for (const auto& name : variantNames) {
      settings.variants.push_back(parseVeryWeakSphDispersionVariant(name, "study.variants"));
    }
    reader.checkAllKeysRead();
    const std::string folder = prepareOutputFolder(opt, sceneFolder, reader);
    const auto wallStart = std::chrono::steady_clock::now();

    AtomicFile curvesFile(folder + "/vwsph_dispersion.csv");
    AtomicFile longWaveFile(folder + "/vwsph_long_wave.csv");
    auto& curves = curvesFile.stream();
    auto& longWave = longWaveFile.stream();
    const std::string setting = std::to_string(dimension) + "-D lattice, " + settings.kernel + " kernel, lambda = " +
                                num(lambda) + ", mu = " + num(mu) + ", rho = " + num(rho) + ", dx = " +
                                num(settings.spacing) + "; c_p = " + num(settings.material.pWaveSpeed()) +
                                ", c_s = " + num(settings.material.sWaveSpeed());
    curves << "# Lattice dispersion of the very weak form SPH's interior stencil (" << setting << ")\n"
           << "# kdx = |k| dx, kh = |k| h (h = h_over_dx dx the smoothing length); phase_speed = omega / (|k| c), "
              "group_speed = (d omega / d|k|) / c, c = c_p for P and c_s for S; alignment = |polarisation . k| / |k|\n";
    curves << "variant,h_over_dx,direction,polarisation,kdx,kh,phase_speed,group_speed,alignment\n";
    curves << std::setprecision(10);
    longWave << "# Long-wave limit of the lattice dispersion (" << setting << ")\n"
             << "# gap = omega(k -> 0) [1/s] (a row that is not translation exact: a spurious elastic foundation); "
                "long_wave_speed = sqrt of the |k|^2 coefficient of omega^2, over c; p_* = phase speed ratio at "
                "|k| dx = pi/4, pi/2; kdx_acc, ppw_acc: the largest |k| dx (2 pi / it, points per wavelength) below "
                "which |p - 1| < " << num(settings.accuracy) << " (NaN: never; whole_band = 1: up to pi)\n";
    longWave << "variant,h_over_dx,direction,polarisation,gap,gap_dx_over_c,long_wave_speed,p_quarter_pi,p_half_pi,"
                "kdx_acc,ppw_acc,whole_band\n";
    longWave << std::setprecision(10);
    std::cout << setting << "\n";
    Tally tally;
    if (dimension == 1) study<1>(settings, curves, longWave, summary, tally);
    else if (dimension == 2) study<2>(settings, curves, longWave, summary, tally);
    else study<3>(settings, curves, longWave, summary, tally);
    curvesFile.commit();
    longWaveFile.commit();

    summary.program = kProgram;
    summary.scene = opt.scenePath.empty() ? "(defaults)" : opt.scenePath;
    summary.method = "very_weak_sph (interior stencil)";
    summary.integrator = "none (semi-discrete analysis)";
    summary.particles = tally.particles;
    summary.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
    summary.figures.push_back({"curves", static_cast<Real>(tally.curves)});
    summary.figures.push_back({"translation_check", tally.worstTranslation});
    summary.figures.push_back({"symbol_asymmetry", tally.worstAsymmetry});
    summary.files.addAll({"vwsph_dispersion.csv", "vwsph_long_wave.csv"});
    summary.conclude(folder, opt.quiet ? nullptr : &std::cout);
    return 0;
  });
}
