// vwsph_interior_spectrum: is the very weak form SPH's interior row stable for central difference?
// For each dimension (1, 2, 3), variant (published, consistent), kernel and smoothing length ratio
// h / dx (and once per dimension the Galerkin variant, whose tent kernel has no such choices), the smallest and largest omega^2 of the interior stencil's symbol over the whole
// Brillouin zone (LatticeDispersion symbolExtremes, k dx = pi j / n on each axis) and where the
// smallest sits. omega^2 < 0 is a mode that grows like exp(sqrt(-omega^2) t) whatever the step:
// no time integrator or step can hold it. Results: docs/theory/very-weak-sph.md, "Why the 3-D
// runs grow".
//
//   vwsph_interior_spectrum [--out DIR] [--samples N] [--kernels cubic_spline,wendland_c2]
//                           [--ratios 1,1.25,1.5,2] [--dimensions 1,2,3]
//
// Writes DIR/vwsph_interior_spectrum.csv (atomically) and prints the table.

#include "numerics/LatticeDispersion.hpp"
#include "spectra/VeryWeakSphDispersion.hpp"
#include "core/AtomicFile.hpp"
#include "core/Error.hpp"
#include "core/Material.hpp"
#include "io/run/RunDriver.hpp"

#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

using namespace mfwave;

namespace {

std::vector<std::string> splitList(const std::string& text) {
  std::vector<std::string> parts;
  std::stringstream in(text);
  for (std::string part; std::getline(in, part, ',');)
    if (!part.empty()) parts.push_back(part);
  return parts;
}

Real parseNumber(const std::string& text, const std::string& key) {
  try {
    std::size_t used = 0;
    const Real value = std::stod(text, &used);
    if (used == text.size()) return value;
  } catch (const std::exception&) {
  }
  throw InputError(key, "'" + text + "' is not a number");
}

struct Options {
  std::string out = "vwsph_interior_spectrum";
  int samples = 24;
  std::vector<std::string> kernels = {"cubic_spline", "wendland_c2"};
  std::vector<Real> ratios = {1, 1.25, 1.5, 2};
  std::vector<int> dimensions = {1, 2, 3};
};

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h") {
      std::cout << "usage: vwsph_interior_spectrum [--out DIR] [--samples N] [--kernels a,b] [--ratios 1,1.5] "
                   "[--dimensions 1,2,3]\n";
      std::exit(0);
    }
    if (i + 1 >= argc) throw InputError(arg, "needs a value");
    const std::string value = argv[++i];
    if (arg == "--out") {
      o.out = value;
    } else if (arg == "--samples") {
      o.samples = static_cast<int>(parseNumber(value, "--samples"));
      if (o.samples < 2 || o.samples > 400) throw InputError("--samples", "must be in [2, 400]");
    } else if (arg == "--kernels") {
      o.kernels = splitList(value);
    } else if (arg == "--ratios") {
      o.ratios.clear();
      for (const std::string& r : splitList(value)) o.ratios.push_back(parseNumber(r, "--ratios"));
    } else if (arg == "--dimensions") {
      o.dimensions.clear();
      for (const std::string& d : splitList(value)) {
        const Real x = parseNumber(d, "--dimensions");
        if (x != 1 && x != 2 && x != 3) throw InputError("--dimensions", "each must be 1, 2 or 3");
        o.dimensions.push_back(static_cast<int>(x));
      }
    } else {
      throw InputError(arg, "unknown option (see --help)");
    }
  }
  return o;
}

template <int D>
void row(VeryWeakSphDispersionVariant variant, const std::string& kernel, Real ratio, int samples, std::ostream& csv) {
  const Material material = Material::fromLame(1, 1, 1);
  const VeryWeakSphLatticeStencil<D> s = veryWeakSphInteriorStencil<D>(variant, kernel, ratio, material);
  const SymbolExtremes<D> e = symbolExtremes(s.stencil, s.spacing, samples);
  const bool galerkin = variant == VeryWeakSphDispersionVariant::Galerkin;
  const std::string kernelName = galerkin ? "tent" : kernel;
  std::ostringstream at;
  for (int a = 0; a < D; ++a) at << (a ? " " : "") << std::setprecision(4) << e.smallestAt(a);
  const Real relative = e.smallest / e.largest;
  csv << D << ',' << veryWeakSphDispersionVariantName(variant) << ',' << kernelName << ',' << ratio << ','
      << std::setprecision(10) << e.smallest << ',' << e.largest << ',' << relative << ',' << at.str() << ','
      << e.largestImaginaryRatio << ',' << e.largestAsymmetryRatio << '\n';
  std::cout << "  " << D << "-D " << std::left << std::setw(11) << veryWeakSphDispersionVariantName(variant)
            << std::setw(15) << kernelName << std::right << " h/dx " << std::setw(5) << ratio
            << "  min omega^2 / max " << std::setw(12) << std::setprecision(4) << relative << "  at k dx = ("
            << at.str() << ")" << (relative < -1e-12 ? "  GROWS" : "") << '\n';
}

template <int D>
void rowsFor(const Options& o, std::ostream& csv) {
  for (const VeryWeakSphDispersionVariant variant :
       {VeryWeakSphDispersionVariant::Published, VeryWeakSphDispersionVariant::Consistent})
    for (const std::string& kernel : o.kernels)
      for (const Real ratio : o.ratios) row<D>(variant, kernel, ratio, o.samples, csv);
  // the tent of half-width dx: kernel and h / dx do not enter
  row<D>(VeryWeakSphDispersionVariant::Galerkin, "cubic_spline", 1, o.samples, csv);
}

}  // namespace

int main(int argc, char** argv) {
  return runDriver("vwsph_interior_spectrum", [&]() -> int {
    const Options o = parse(argc, argv);
    std::filesystem::create_directories(o.out);
    AtomicFile file(o.out + "/vwsph_interior_spectrum.csv");
    std::ostream& csv = file.stream();
    csv << "dimension,variant,kernel,h_over_dx,min_omega2,max_omega2,min_over_max,min_at_kdx,"
           "imaginary_ratio,asymmetry_ratio\n";
    std::cout << "interior symbol of the very weak SPH (lambda = mu = rho = 1, dx = 1), " << o.samples
              << " samples per axis over [0, pi]^D\n";
    for (const int d : o.dimensions) {
      if (d == 1) rowsFor<1>(o, csv);
      if (d == 2) rowsFor<2>(o, csv);
      if (d == 3) rowsFor<3>(o, csv);
    }
    file.commit();
    std::cout << "wrote " << o.out << "/vwsph_interior_spectrum.csv\n";
    return 0;
  });
}
