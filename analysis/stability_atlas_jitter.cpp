#include "stability_atlas_jitter.hpp"

#include "spectra/JitteredCloud.hpp"
#include "core/Error.hpp"
#include "io/scene/Format.hpp"

#include <algorithm>
#include <iomanip>
#include <iostream>

namespace mfwave {

void addJitterAtlasKeys(SceneSchema& schema) {
  using T = ValueType;
  schema.add("jitter", T::Table).describedAs(
      "irregular clouds: each method's whole spectrum on a periodic cloud of lattice sites moved at random");
  schema.add("jitter.enabled", T::Boolean).defaultsTo("true").describedAs("examine the jittered clouds");
  schema.add("jitter.methods", T::StringArray).withUnit("-")
      .defaultsTo(scene::tomlArray(jitteredCloudMethodNames()))
      .oneOf(jitteredCloudMethodNames())
      .describedAs("methods assembled on the clouds (finite differences and the Galerkin variant are lattice "
                   "schemes; rbcm's global functions cannot be folded exactly)");
  schema.add("jitter.dimensions", T::NumberArray).withUnit("-").defaultsTo("[1.0, 2.0, 3.0]").between(1, 3)
      .describedAs("cloud dimensions");
  schema.add("jitter.ulsph_dimensions", T::NumberArray).withUnit("-").defaultsTo("[1.0, 2.0, 3.0]").between(1, 3)
      .describedAs("dimensions of the updated-Lagrangian SPH (three right-hand sides per unknown of the tile; "
                   "3-D: 4 to 18 s a cloud, 4.5 minutes in all)");
  schema.add("jitter.fractions", T::NumberArray).withUnit("dx").defaultsTo("[0.0, 0.1, 0.25]").between(0, 0.45)
      .describedAs("largest random offset per axis, as a fraction of the spacing (0: the lattice, a check)");
  schema.add("jitter.seeds", T::Integer).withUnit("-").defaultsTo("3").between(1, 100).describedAs(
      "random clouds per jittered point (the CSV has one row each)");
  schema.add("jitter.cells_1d", T::Integer).withUnit("-").defaultsTo("32").between(4, 64).describedAs(
      "tile sites in 1-D (also the points per wavelength of the lowest modes)");
  schema.add("jitter.cells_2d", T::Integer).withUnit("-").defaultsTo("12").between(4, 64).describedAs(
      "tile sites per axis in 2-D");
  schema.add("jitter.cells_3d", T::Integer).withUnit("-").defaultsTo("6").between(4, 16).describedAs(
      "tile sites per axis in 3-D (6: 648 unknowns, about 1 s a cloud; 8: 1,536 unknowns, about 40 s; the tile "
      "samples k dx in steps of 2 pi / cells only)");
  schema.add("jitter.confirm_steps", T::Integer).withUnit("-").defaultsTo("2000").between(0, 1000000).describedAs(
      "central-difference steps at 0.9 of each cloud's limit from random data, to confirm its predicted growth "
      "or boundedness (0: no runs)");
  schema.add("jitter.smoothing_length_ratios", T::NumberArray).withUnit("-").defaultsTo("[1.0, 1.3, 2.0]")
      .positive().describedAs("SPH h / dx (kernel: study.kernel); too wide for a tile: skipped");
  schema.add("jitter.rk_support_ratios", T::NumberArray).withUnit("-").defaultsTo("[1.5, 2.0, 2.5]").positive()
      .describedAs("RK a / dx (order: study.rk_order)");
}

JitterAtlasSettings readJitterAtlasSettings(SceneReader& reader) {
  JitterAtlasSettings s;
  s.enabled = reader.boolean("jitter.enabled");
  s.methods = reader.strings("jitter.methods");
  s.dimensions = reader.wholeNumbers("jitter.dimensions");
  s.ulsphDimensions = reader.wholeNumbers("jitter.ulsph_dimensions");
  s.jitters = reader.numbers("jitter.fractions");
  s.seeds = static_cast<int>(reader.integer("jitter.seeds"));
  s.cells[1] = static_cast<int>(reader.integer("jitter.cells_1d"));
  s.cells[2] = static_cast<int>(reader.integer("jitter.cells_2d"));
  s.cells[3] = static_cast<int>(reader.integer("jitter.cells_3d"));
  s.confirmSteps = reader.integer("jitter.confirm_steps");
  s.smoothingRatios = reader.numbers("jitter.smoothing_length_ratios");
  s.rkSupports = reader.numbers("jitter.rk_support_ratios");
  return s;
}

namespace {

template <int D>
void writeDimension(const JitterAtlasSettings& s, const LatticeMethodSettings& defaults, std::ostream& csv,
                    JitterAtlasCounts& counts) {
  for (const std::string& method : s.methods) {
    const bool ul = method.rfind("ulsph", 0) == 0;
    if (ul && std::find(s.ulsphDimensions.begin(), s.ulsphDimensions.end(), D) == s.ulsphDimensions.end()) continue;
    const bool rk = method == "rkcm";
    long grew = 0, rows = 0;
    for (Real support : rk ? s.rkSupports : s.smoothingRatios)
      for (Real jitter : s.jitters)
        for (int seed = 1; seed <= (jitter > 0 ? s.seeds : 1); ++seed) {
          LatticeMethodSettings settings = defaults;
          (rk ? settings.rkSupportRatio : settings.smoothingLengthRatio) = support;
          JitteredCloudReport r;
          try {
            r = jitteredCloudSpectrum<D>(method, settings, s.cells[D], jitter, static_cast<std::uint64_t>(seed),
                                        s.confirmSteps);
          } catch (const InputError& e) {
            r.status = std::string("skipped: ") + e.what();
          }
          csv << D << ',' << method << ',' << (rk ? "m=" + std::to_string(settings.rkOrder) : settings.kernel) << ','
              << (rk ? "a/dx" : "h/dx") << ',' << support << ',' << jitter << ',' << seed << ",\"" << r.status
              << "\"," << r.cells << ',' << r.closestPair << ',' << r.smallestOverLargest << ',' << r.imaginaryRatio
              << ',' << r.courant << ',' << r.spuriousLowModes << ',' << r.lowestModeError << ','
              << r.quadraticResidual << ',' << r.predictedLogGrowth << ',' << r.measuredLogGrowth << ",\""
              << r.confirmation << "\"," << r.seconds << '\n';
          if (r.confirmation.rfind("CONTRADICTS", 0) == 0) ++counts.contradicted;
          if (r.confirmation.find("as predicted") != std::string::npos) ++counts.confirmed;
          ++counts.points;
          ++rows;
          if (r.status == "growing") ++counts.growing, ++grew;
          if (r.status.rfind("fails", 0) == 0) ++counts.failed;
        }
    std::cout << "  " << std::left << std::setw(17) << method << std::right << D << "-D: " << rows
              << " jittered clouds, " << grew << " growing\n";
  }
}

}  // namespace

JitterAtlasCounts writeJitterAtlas(const JitterAtlasSettings& s, const LatticeMethodSettings& defaults,
                                   std::ostream& csv) {
  csv << "# Whole spectra on periodic jittered clouds (lib/spectra/JitteredCloud; lambda = mu = rho = 1, dx = 1): "
         "omega2_min_over_max and imaginary_ratio above the tolerance (1e-9; 1e-6 for ulsph) mean growing modes; "
         "cd_courant = c_p dt / dx at 2 / omega_max; lowest_mode_error at `cells` points per wavelength; "
         "quadratic_residual = |A u - M a| / c_p^2 for u = x^2 / 2; the run: central difference at 0.9 of the limit "
         "from random data, ln growth predicted by the spectrum and measured\n"
      << "dimension,method,family,knob,value,jitter,seed,status,cells,closest_pair,omega2_min_over_max,"
         "imaginary_ratio,cd_courant,spurious_low_modes,lowest_mode_error,quadratic_residual,predicted_log_growth,"
         "measured_log_growth,confirmation,seconds\n"
      << std::setprecision(8);
  JitterAtlasCounts counts;
  if (!s.enabled) return counts;
  for (int d : s.dimensions) {
    if (d == 1) writeDimension<1>(s, defaults, csv, counts);
    else if (d == 2) writeDimension<2>(s, defaults, csv, counts);
    else writeDimension<3>(s, defaults, csv, counts);
  }
  return counts;
}

}  // namespace mfwave
