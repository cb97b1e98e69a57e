// stability: critical central-difference time step of explicit strong-form collocation for the
// bar of Luo, Liu and Huang (2011), section 4 (rho = 1, E = 10, L = 10, Ns = Nc = 21, m = 2), three
// ways: von Neumann on a long uniform line (eqs. (34)-(41)), eigenvalues of the assembled
// constrained bar, and bisection on central-difference runs of that bar. RKCM (cubic B-spline RK
// shape functions, support radius a) and RBCM (inverse multiquadric, shape parameter a_r), beside
// the published Tables 1 and 2 (read as c * dt with c = 1). Results: docs/studies/rkcm.md.
//
//   stability [--scene data/scenes/collocation-stability.toml] [--set study.rk_support_ratios=[3.3]] [--out DIR]
//
// The scene is optional: every key has a default (the paper's setting). Writes stability.csv,
// scene.resolved.toml and summary.json; plot with analysis/plot_stability.py.

#include "spectra/CollocationStability.hpp"
#include "core/AtomicFile.hpp"
#include "core/Error.hpp"
#include "io/run/DriverCommandLine.hpp"
#include "io/run/RunDriver.hpp"
#include "io/run/SceneDriver.hpp"
#include "io/run/RunSummary.hpp"
#include "io/run/ShippedData.hpp"
#include "io/scene/LoadScene.hpp"
#include "methods/collocation/RadialBasisShapeFunctions.hpp"
#include "methods/collocation/ReproducingKernelShapeFunctions.hpp"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using namespace mfwave;

namespace {

const char* kProgram = "stability";

SceneSchema stabilitySchema() {
  SceneSchema schema;
  schema.add("study", ValueType::Table).describedAs("the stability study (every key has a default)");
  schema.add("study.length", ValueType::Number).withUnit("m").defaultsTo("10.0").positive().describedAs("bar length L");
  schema.add("study.nodes", ValueType::Integer).withUnit("-").defaultsTo("21").atLeast(5).describedAs(
      "nodes = collocation points Ns = Nc on the bar (h = L / (nodes - 1))");
  schema.add("study.modulus", ValueType::Number).withUnit("Pa").defaultsTo("10.0").positive().describedAs("Young's modulus E");
  schema.add("study.density", ValueType::Number).withUnit("kg/m").defaultsTo("1.0").positive().describedAs("line density rho");
  schema.add("study.order", ValueType::Integer).withUnit("-").defaultsTo("2").between(2, 3).describedAs(
      "RK basis order m (2 or 3: collocation needs second derivatives)");
  schema.add("study.rk_support_ratios", ValueType::NumberArray).withUnit("-").defaultsTo("[3.3, 4.3, 5.3, 6.3]")
      .positive().describedAs("RKCM support radius a over h");
  schema.add("study.rb_shape_ratios", ValueType::NumberArray).withUnit("-").defaultsTo("[3.0, 4.0, 5.0, 6.0]")
      .positive().describedAs("RBCM inverse-multiquadric shape parameter a_r over h");
  schema.add("study.rk_line_nodes", ValueType::Integer).withUnit("-").defaultsTo("201").atLeast(21).describedAs(
      "nodes of the long line of the RK von Neumann analysis (central row)");
  schema.add("study.rb_line_nodes", ValueType::Integer).withUnit("-").defaultsTo("21").atLeast(5).describedAs(
      "nodes of the line of the RBF von Neumann analysis (central row; global functions)");
  schema.add("study.samples", ValueType::Integer).withUnit("-").defaultsTo("4000").atLeast(8).describedAs(
      "wavenumbers in (0, pi/h] of the von Neumann sweep (then refined)");
  schema.add("study.bisection_steps", ValueType::Integer).withUnit("-").defaultsTo("20000").atLeast(100).describedAs(
      "least steps of each central-difference run of the bisection");
  schema.add("study.bisection_tolerance", ValueType::Number).withUnit("-").defaultsTo("1e-4").positive().describedAs(
      "relative width of the final bisection bracket");
  schema.add("study.rk_reference", ValueType::String).withUnit("").defaultsTo(
      "\"data/reference/luo2011-table1-rkcm-critical-dt.csv\"").describedAs("published Table 1 (CSV; '' for none)");
  schema.add("study.rb_reference", ValueType::String).withUnit("").defaultsTo(
      "\"data/reference/luo2011-table2-rbcm-critical-dt.csv\"").describedAs("published Table 2 (CSV; '' for none)");
  schema.add("output", ValueType::Table).describedAs("where results go");
  schema.add("output.folder", ValueType::String).defaultsTo("\"out/stability\"").describedAs("output folder");
  return schema;
}

struct Published {
  Real predicted = std::nan(""), numerical = std::nan("");
};

// ratio (rounded to 1e-6) -> published columns; lines starting with '#' and the header are skipped.
std::map<long, Published> readReference(const std::string& path, const std::string& key) {
  std::map<long, Published> table;
  if (path.empty()) return table;
  // A relative path not in the working folder is looked up in the shipped data (an installed tool).
  const std::string file = resolveDataFile(path, key);
  std::ifstream in(file);
  if (!in) throw InputError(key, "cannot read '" + file + "'");
  std::string line;
  bool header = true;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (header) { header = false; continue; }
    std::stringstream s(line);
    std::string a, b, c;
    std::getline(s, a, ',');
    std::getline(s, b, ',');
    std::getline(s, c, ',');
    table[std::lround(std::stod(a) * 1e6)] = {std::stod(b), c == "nan" ? std::nan("") : std::stod(c)};
  }
  return table;
}

struct Row {
  std::string method;
  Real ratio;
  VonNeumannResult vonNeumann;
  EigenvalueStability eigen;
  BisectionResult bisection;
  Published published;
};

std::string num(Real x, int digits = 5) {
  if (std::isnan(x)) return "nan";
  std::ostringstream s;
  s << std::setprecision(digits) << x;
  return s.str();
}

}  // namespace

int main(int argc, char** argv) {
  const SceneSchema schema = stabilitySchema();
  DriverCommandLine cli(kProgram,
                        "stability: critical step of RK and RBF collocation with central difference (Luo-Liu-Huang "
                        "bar): von Neumann, eigenvalues, bisection on runs. The scene is optional.",
                        schema.describe(), false);
  if (const auto exit = cli.parse(argc, argv)) return *exit;

  return runDriver(kProgram, [&]() -> int {
    const auto& opt = cli.options();
    SceneReader reader = loadDriverScene(opt, schema);
    BarProblem bar;
    bar.length = reader.number("study.length");
    bar.nodes = reader.integer("study.nodes");
    bar.modulus = reader.number("study.modulus");
    bar.density = reader.number("study.density");
    const int order = static_cast<int>(reader.integer("study.order"));
    const auto rkRatios = reader.numbers("study.rk_support_ratios");
    const auto rbRatios = reader.numbers("study.rb_shape_ratios");
    const Index rkLine = reader.integer("study.rk_line_nodes"), rbLine = reader.integer("study.rb_line_nodes");
    const int samples = static_cast<int>(reader.integer("study.samples"));
    BisectionOptions bisection;
    bisection.minSteps = reader.integer("study.bisection_steps");
    bisection.relativeTolerance = reader.number("study.bisection_tolerance");
    const auto rkPublished = readReference(reader.string("study.rk_reference"), "study.rk_reference");
    const auto rbPublished = readReference(reader.string("study.rb_reference"), "study.rb_reference");
    const std::string sceneFolder = reader.string("output.folder");  // read always: --out overrides it
    reader.checkAllKeysRead();
    const std::string folder = prepareOutputFolder(opt, sceneFolder, reader);
    const auto wallStart = std::chrono::steady_clock::now();
    const Real h = bar.spacing(), c = bar.waveSpeed();
    const Coordinates<1> barNodes = uniformLine(bar.nodes, h);

    std::vector<Row> rows;
    auto analyse = [&](const std::string& method, Real ratio, const ShapeFunctions<1>& line, Index lineNodes,
                       const ShapeFunctions<1>& barShapes, const Published& published) {
      Row row{method, ratio, {}, {}, {}, published};
      const CollocationRows stencils = collocationRows(line, uniformLine(lineNodes, h), lineNodes / 2, h);
      row.vonNeumann = vonNeumannStability(stencils.amplification, h, c, samples);
      const Eigen::MatrixXd k = constrainedBarStiffness(barShapes, bar);
      row.eigen = eigenvalueStability(k);
      const Real guess = row.eigen.unconditionallyUnstable
                             ? (row.vonNeumann.unconditionallyUnstable ? 0.3 * h / c : row.vonNeumann.criticalStep)
                             : row.eigen.criticalStep;
      BisectionOptions options = bisection;
      options.horizon = static_cast<Real>(options.minSteps) * guess;
      row.bisection = bisectCriticalStep(k, guess, options);
      if (!opt.quiet) std::cerr << "  done " << method << " ratio " << ratio << '\n';
      rows.push_back(row);
    };
    for (Real ratio : rkRatios) {
      const Real a = ratio * h;
      const ReproducingKernelShapeFunctions<1> line(uniformLine(rkLine, h), order, a);
      const ReproducingKernelShapeFunctions<1> shapes(barNodes, order, a);
      const auto it = rkPublished.find(std::lround(ratio * 1e6));
      analyse("rkcm", ratio, line, rkLine, shapes, it == rkPublished.end() ? Published{} : it->second);
    }
    for (Real ratio : rbRatios) {
      const RadialBasisFunction g(RadialBasisKind::InverseMultiquadric, ratio * h);
      const RadialBasisShapeFunctions<1> line(uniformLine(rbLine, h), g);
      const RadialBasisShapeFunctions<1> shapes(barNodes, g);
      const auto it = rbPublished.find(std::lround(ratio * 1e6));
      analyse("rbcm", ratio, line, rbLine, shapes, it == rbPublished.end() ? Published{} : it->second);
    }

    AtomicFile table(folder + "/stability.csv");
    auto& out = table.stream();
    out << "# Critical central-difference step of collocation for the Luo-Liu-Huang bar: c = " << num(c, 8)
        << " m/s (E = " << bar.modulus << ", rho = " << bar.density << "), L = " << bar.length
        << ", h = " << h << ", Ns = Nc = " << bar.nodes << ", RK order m = " << order << "\n"
        << "# *_dt columns are time steps [s]; *_c_dt columns are c * dt [m]. The published values are read as c * dt "
           "(as if c = 1).\n"
        << "# von_neumann: long uniform line, central row; eigen: constrained bar, 2/sqrt(lambda_max); bisection: "
           "largest bounded dt of central-difference runs (>= " << bisection.minSteps << " steps). 0 = unconditionally unstable.\n";
    out << "method,ratio,von_neumann_dt,von_neumann_c_dt,von_neumann_kh,eigen_dt,eigen_c_dt,eigen_growth_rate,"
           "eigen_verdict,bisection_dt,bisection_c_dt,published_predicted_c_dt,published_numerical_c_dt\n";
    std::cout << "c = " << num(c) << ", h = " << h << "; values are c * dt (published: read as c * dt)\n";
    std::cout << std::left << std::setw(6) << "method" << std::right << std::setw(7) << "ratio" << std::setw(12)
              << "vonNeumann" << std::setw(12) << "eigen" << std::setw(12) << "bisection" << std::setw(12)
              << "pub.pred" << std::setw(12) << "pub.num" << "  verdict\n";
    RunSummary summary;
    summary.program = kProgram;
    summary.scene = opt.scenePath.empty() ? "(defaults)" : opt.scenePath;
    summary.method = "rkcm, rbcm";
    summary.integrator = "central_difference";
    summary.particles = bar.nodes;
    for (const Row& r : rows) {
      const Real vn = r.vonNeumann.criticalStep, ev = r.eigen.criticalStep, bi = r.bisection.criticalStep;
      out << r.method << ',' << num(r.ratio, 6) << ',' << num(vn, 8) << ',' << num(c * vn, 8) << ','
          << num(r.vonNeumann.khAtMin, 6) << ',' << num(ev, 8) << ',' << num(c * ev, 8) << ','
          << num(r.eigen.growthRate, 6) << ",\"" << r.eigen.verdict() << "\"," << num(bi, 8) << ',' << num(c * bi, 8)
          << ',' << num(r.published.predicted, 6) << ',' << num(r.published.numerical, 6) << '\n';
      auto cell = [](Real x, bool unstable) { return unstable ? std::string("unstable") : num(x, 5); };
      std::cout << std::left << std::setw(6) << r.method << std::right << std::setw(7) << r.ratio << std::setw(12)
                << cell(c * vn, r.vonNeumann.unconditionallyUnstable) << std::setw(12)
                << cell(c * ev, r.eigen.unconditionallyUnstable) << std::setw(12)
                << cell(c * bi, r.bisection.unconditionallyUnstable) << std::setw(12) << num(r.published.predicted)
                << std::setw(12) << (std::isnan(r.published.numerical) ? std::string("unstable") : num(r.published.numerical))
                << "  " << r.eigen.verdict() << '\n';
      summary.steps += r.bisection.runs;
      summary.figures.push_back({r.method + "_" + num(r.ratio, 3) + "_eigen_c_dt", c * ev});
    }
    table.commit();
    summary.wallSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
    summary.notes.add("steps: number of bisection runs in total");
    summary.files.add("stability.csv");
    summary.conclude(folder, opt.quiet ? nullptr : &std::cout);
    return 0;
  });
}
