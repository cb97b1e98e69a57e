// dispersion: normalised phase speed p(kh) = omega / (c k) (Luo-Liu-Huang eq. (45)) and group speed
// (d omega / dk) / c of RK collocation (cubic B-spline, support radius a, basis order m) and radial
// basis collocation (inverse multiquadric, shape parameter a_r) on a uniform line, from the central
// node's collocation stencils: K_IJ = -psi_I,xx(x_J), M_IJ = psi_I(x_J). Like the paper's Fig. 2.
// Results: docs/studies/rkcm.md.
//
//   dispersion [--scene data/scenes/collocation-dispersion.toml] [--set 'study.orders=[2]'] [--out DIR]
//
// The scene is optional: every key has a default. Writes dispersion.csv, scene.resolved.toml and
// summary.json; plot with analysis/plot_dispersion.py.

#include "spectra/CollocationStability.hpp"
#include "core/AtomicFile.hpp"
#include "io/run/DriverCommandLine.hpp"
#include "io/run/RunDriver.hpp"
#include "io/run/SceneDriver.hpp"
#include "io/run/RunSummary.hpp"
#include "io/scene/LoadScene.hpp"
#include "methods/collocation/RadialBasisShapeFunctions.hpp"
#include "methods/collocation/ReproducingKernelShapeFunctions.hpp"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

using namespace mfwave;

namespace {

const char* kProgram = "dispersion";

SceneSchema dispersionSchema() {
  SceneSchema schema;
  schema.add("study", ValueType::Table).describedAs("the dispersion study (every key has a default)");
  schema.add("study.spacing", ValueType::Number).withUnit("m").defaultsTo("0.5").positive().describedAs(
      "node spacing h (p and the group speed depend on kh only)");
  schema.add("study.orders", ValueType::NumberArray).withUnit("-").defaultsTo("[2.0, 3.0]").between(2, 3).describedAs(
      "RK basis orders m");
  schema.add("study.rk_support_ratios", ValueType::NumberArray).withUnit("-").defaultsTo("[3.3, 4.3, 5.3, 6.3]")
      .positive().describedAs("RKCM support radius a over h");
  schema.add("study.rb_shape_ratios", ValueType::NumberArray).withUnit("-").defaultsTo("[3.0, 4.0, 5.0, 6.0]")
      .positive().describedAs("RBCM inverse-multiquadric shape parameter a_r over h");
  schema.add("study.rk_line_nodes", ValueType::Integer).withUnit("-").defaultsTo("201").atLeast(21).describedAs(
      "nodes of the RK line (central node's stencils)");
  schema.add("study.rb_line_nodes", ValueType::Integer).withUnit("-").defaultsTo("161").atLeast(5).describedAs(
      "nodes of the RBF line (central node's stencils; global functions: a short line adds boundary effects)");
  schema.add("study.points", ValueType::Integer).withUnit("-").defaultsTo("200").atLeast(2).describedAs(
      "values of kh in (0, pi]");
  schema.add("output", ValueType::Table).describedAs("where results go");
  schema.add("output.folder", ValueType::String).defaultsTo("\"out/dispersion\"").describedAs("output folder");
  return schema;
}

}  // namespace

int main(int argc, char** argv) {
  const SceneSchema schema = dispersionSchema();
  DriverCommandLine cli(kProgram,
                        "dispersion: phase and group speed of RK and RBF collocation against kh (Luo-Liu-Huang eq. 45). "
                        "The scene is optional.",
                        schema.describe(), false);
  if (const auto exit = cli.parse(argc, argv)) return *exit;

  return runDriver(kProgram, [&]() -> int {
    const auto& opt = cli.options();
    SceneReader reader = loadDriverScene(opt, schema);
    const Real h = reader.number("study.spacing");
    std::vector<int> orders;
    for (Real m : reader.numbers("study.orders")) {
      if (m != std::floor(m)) reader.fail("study.orders", "orders are whole numbers");
      orders.push_back(static_cast<int>(m));
    }
    const auto rkRatios = reader.numbers("study.rk_support_ratios");
    const auto rbRatios = reader.numbers("study.rb_shape_ratios");
    const Index rkLine = reader.integer("study.rk_line_nodes"), rbLine = reader.integer("study.rb_line_nodes");
    const int points = static_cast<int>(reader.integer("study.points"));
    const std::string sceneFolder = reader.string("output.folder");  // read always: --out overrides it
    reader.checkAllKeysRead();
    const std::string folder = prepareOutputFolder(opt, sceneFolder, reader);
    const auto wallStart = std::chrono::steady_clock::now();

    AtomicFile table(folder + "/dispersion.csv");
    auto& out = table.stream();
    out << "# Normalised phase speed p = omega/(c k) (Luo-Liu-Huang eq. 45) and group speed (d omega/dk)/c of "
           "collocation on a uniform line, h = " << h << "; NaN: no real frequency\n";
    out << "method,order,ratio,kh,phase_speed,group_speed\n";
    out << std::setprecision(10);
    std::cout << std::left << std::setw(6) << "method" << std::right << std::setw(6) << "order" << std::setw(7)
              << "ratio" << std::setw(12) << "p(0.05)" << std::setw(12) << "p(pi/2)" << std::setw(12) << "p(pi)"
              << std::setw(14) << "min group" << '\n';
    auto write = [&](const std::string& method, const std::string& order, Real ratio, const CollocationRows& rows) {
      Real minGroup = 1e300;
      for (int s = 1; s <= points; ++s) {
        const Real kh = kPi * s / points;
        const Real p = phaseSpeed(rows.stiffnessColumn, rows.massColumn, kh, h);
        const Real g = groupSpeed(rows.stiffnessColumn, rows.massColumn, kh, h);
        if (std::isfinite(g)) minGroup = std::min(minGroup, g);
        out << method << ',' << order << ',' << ratio << ',' << kh << ',' << p << ',' << g << '\n';
      }
      std::cout << std::left << std::setw(6) << method << std::right << std::setw(6) << order << std::setw(7) << ratio
                << std::setprecision(6) << std::setw(12) << phaseSpeed(rows.stiffnessColumn, rows.massColumn, 0.05, h)
                << std::setw(12) << phaseSpeed(rows.stiffnessColumn, rows.massColumn, kPi / 2, h) << std::setw(12)
                << phaseSpeed(rows.stiffnessColumn, rows.massColumn, kPi, h) << std::setw(14) << minGroup << '\n';
    };
    long cases = 0;
    for (int m : orders)
      for (Real ratio : rkRatios) {
        const ReproducingKernelShapeFunctions<1> line(uniformLine(rkLine, h), m, ratio * h);
        write("rkcm", std::to_string(m), ratio, collocationRows(line, uniformLine(rkLine, h), rkLine / 2, h));
        ++cases;
      }
    for (Real ratio : rbRatios) {
      const RadialBasisShapeFunctions<1> line(uniformLine(rbLine, h),
                                              RadialBasisFunction(RadialBasisKind::InverseMultiquadric, ratio * h));
      write("rbcm", "-", ratio, collocationRows(line, uniformLine(rbLine, h), rbLine / 2, h));
      ++cases;
    }
    table.commit();

    RunSummary summary;
    summary.program = kProgram;
    summary.scene = opt.scenePath.empty() ? "(defaults)" : opt.scenePath;
    summary.method = "rkcm, rbcm";
    summary.integrator = "none (semi-discrete analysis)";
    summary.particles = rkLine;
    summary.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
    summary.figures.push_back({"cases", static_cast<Real>(cases)});
    summary.files.add("dispersion.csv");
    summary.conclude(folder, opt.quiet ? nullptr : &std::cout);
    return 0;
  });
}
