// The stability atlas run as a user runs it, on a representative subset: every method in 1-D with
// the 0.98 / 1.02 confirmations of central difference and classic RK4 (consistent mass included),
// the RK collocation supports that grow in 2-D and 3-D, and the integrators' limits.

#include "support/StudyRun.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using Row = std::map<std::string, std::string>;

mfwave::testing::StudyOutcome run(const std::string& arguments, const std::string& name) {
  return mfwave::testing::runStudy(STABILITY_ATLAS_EXECUTABLE, std::string(SCENES_FOLDER) + "/stability-atlas.toml",
                                   arguments, "atlas-" + name);
}

// Rows of a CSV with a header (comment lines skipped; quoted fields hold no commas here).
std::vector<Row> table(const fs::path& path) {
  std::ifstream in(path);
  std::string line;
  std::vector<std::string> header;
  std::vector<Row> rows;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> fields;
    std::stringstream s(line);
    std::string f;
    while (std::getline(s, f, ',')) {
      if (f.size() >= 2 && f.front() == '"' && f.back() == '"') f = f.substr(1, f.size() - 2);
      fields.push_back(f);
    }
    if (header.empty()) {
      header = fields;
      continue;
    }
    Row r;
    for (std::size_t i = 0; i < header.size() && i < fields.size(); ++i) r[header[i]] = fields[i];
    rows.push_back(r);
  }
  return rows;
}

const Row& find(const std::vector<Row>& rows, const std::map<std::string, std::string>& match) {
  for (const Row& r : rows) {
    bool all = true;
    for (const auto& [k, v] : match) all = all && r.count(k) && r.at(k) == v;
    if (all) return r;
  }
  throw std::runtime_error("no row matches");
}

// Runs the atlas into a fresh `out` with `settings`; true when it exited 0 (else the log is shown).
bool ranCleanly(const fs::path& out, const std::string& settings, const std::string& name) {
  fs::remove_all(out);
  const auto outcome = run("--out " + out.string() + settings, name);
  EXPECT_TRUE(outcome.exited && outcome.exitCode == 0) << outcome.log;
  return outcome.exited && outcome.exitCode == 0;
}

}  // namespace

TEST(StabilityAtlasStudy, EveryMethodIn1dIsConfirmedAtBothSidesOfItsLimit) {
  const fs::path out = fs::temp_directory_path() / "mfwave-atlas-1d";
  ASSERT_TRUE(ranCleanly(out,
                         " --set 'study.dimensions=[1]' --set 'study.kernels=[\"cubic_spline\", \"gaussian\"]'"
                         " --set 'study.smoothing_length_ratios=[1.3, 3.0]' --set 'study.ulsph_kernels=[\"cubic_spline\"]'"
                         " --set 'study.ulsph_smoothing_length_ratios=[1.3]' --set 'study.rk_orders=[2]'"
                         " --set 'study.rk_support_ratios=[2.5]' --set 'study.rb_shape_ratios=[3.0]'"
                         " --set 'study.poisson_ratios=[0.25]' --set 'jitter.dimensions=[1]'",
                         "1d"));
  // Central difference, classic RK4 and Newmark with beta = 1/12 (limit sqrt 6 / omega_max) at 0.98
  // and 1.02 of each method's exact limit on its small periodic lattice (the collocation methods
  // with their consistent mass, solved every step): bounded for 10^4 steps below, stopped by the
  // monitor above.
  const auto confirmations = table(out / "confirmations.csv");
  int checked = 0;
  for (const Row& r : confirmations) {
    ASSERT_NE(r.at("integrator"), "-") << r.at("method") << " was not run";
    ++checked;
    EXPECT_EQ(r.at("verdict"), "as predicted") << r.at("method") << ' ' << r.at("integrator") << ' ' << r.at("fraction");
    if (std::stod(r.at("fraction")) < 1) {
      EXPECT_EQ(r.at("outcome"), "bounded");
      EXPECT_EQ(r.at("steps"), "10000");
    } else {
      EXPECT_EQ(r.at("outcome"), "stopped");
    }
  }
  // finite difference, three very weak SPH variants, RK and RB collocation, two UL-SPH: 8 methods x
  // 3 integrators x 2 fractions.
  EXPECT_EQ(checked, 48);
  const Row& newmark = find(confirmations, {{"method", "finite_difference"}, {"integrator", "newmark:fox_goodwin"},
                                            {"fraction", "0.98"}});
  const Row& cd = find(confirmations, {{"method", "finite_difference"}, {"integrator", "central_difference"},
                                       {"fraction", "0.98"}});
  EXPECT_NEAR(std::stod(newmark.at("dt")) / std::stod(cd.at("dt")), std::sqrt(6.0) / 2, 1e-6);
  const auto atlas = table(out / "atlas.csv");
  // The finite-difference limit is c dt / dx = 1 exactly; ppw for 1 %: 2 pi / kdx with
  // sinc(kdx / 2) = 0.99, kdx = 0.4903, 12.81 points.
  const Row& fd = find(atlas, {{"method", "finite_difference"}});
  EXPECT_NEAR(std::stod(fd.at("cd_courant")), 1.0, 1e-9);
  EXPECT_NEAR(std::stod(fd.at("ppw_p_axis")), 12.81, 0.1);
  // The Galerkin very weak SPH has no growing mode at any support; the Gaussian kernel at
  // h / dx = 3 makes the published and consistent rows grow.
  for (const char* h : {"1.3", "3"})
    EXPECT_EQ(find(atlas, {{"method", "vwsph_galerkin"}, {"family", "gaussian"}, {"value", h}}).at("status"), "ok");
  EXPECT_EQ(find(atlas, {{"method", "vwsph_published"}, {"family", "gaussian"}, {"value", "3"}}).at("status"),
            "growing");
  // Classic RK4's imaginary-axis limit, 2 sqrt 2.
  const auto integrators = table(out / "integrators.csv");
  EXPECT_NEAR(std::stod(find(integrators, {{"integrator", "arkode:classic_rk4"}}).at("omega_dt_limit")),
              2 * std::sqrt(2.0), 1e-9);
  // Irregular clouds in 1-D: five methods x three supports x (the lattice + 2 jitters x 3 seeds).
  const auto jitter = table(out / "jitter.csv");
  EXPECT_EQ(jitter.size(), 105u);
  for (const Row& r : jitter) {
    // Without jitter every method that builds is stable, and RK collocation and the consistent very
    // weak SPH reproduce quadratic fields on every cloud they build on.
    if (r.at("jitter") == "0") {
      EXPECT_EQ(r.at("status"), "ok") << r.at("method") << ' ' << r.at("value");
    }
    EXPECT_EQ(r.at("confirmation").rfind("CONTRADICTS", 0), std::string::npos) << r.at("method");
    if ((r.at("method") == "rkcm" || r.at("method") == "vwsph_consistent") && r.at("status").rfind("fails", 0) != 0) {
      EXPECT_LT(std::stod(r.at("quadratic_residual")), 1e-9) << r.at("method");
    }
  }
  // The consistent very weak SPH at h = dx cannot complete its rows once the particles move.
  EXPECT_EQ(find(jitter, {{"method", "vwsph_consistent"}, {"value", "1"}, {"jitter", "0.25"}}).at("status").rfind(
                "fails", 0),
            0u);
  EXPECT_TRUE(fs::exists(out / "summary.json"));
}

TEST(StabilityAtlasStudy, ImplicitConfirmationsOnTooDenseOperatorsAreNotRunAndSaySo) {
  const fs::path out = fs::temp_directory_path() / "mfwave-atlas-implicit";
  ASSERT_TRUE(ranCleanly(out,
                         " --set 'study.dimensions=[1]' --set 'study.methods=[\"finite_difference\"]'"
                         " --set 'study.poisson_ratios=[0.25]' --set jitter.enabled=false"
                         " --set confirm.implicit_max_nonzeros=10",
                         "implicit"));
  const auto confirmations = table(out / "confirmations.csv");
  // The 8-node periodic lattice's Laplacian has 24 nonzeros: Newmark is not run, the explicit two are.
  const Row& newmark = find(confirmations, {{"integrator", "newmark:fox_goodwin"}});
  EXPECT_EQ(newmark.at("outcome"), "not run: an implicit step on an operator of 24 nonzeros "
                                   "(confirm.implicit_max_nonzeros)");
  EXPECT_EQ(confirmations.size(), 5u);
  EXPECT_EQ(find(confirmations, {{"integrator", "central_difference"}, {"fraction", "1.02"}}).at("outcome"), "stopped");
}

TEST(StabilityAtlasStudy, RkCollocationGrowsAtWideSupportsIn2dAnd3d) {
  const fs::path out = fs::temp_directory_path() / "mfwave-atlas-rk";
  ASSERT_TRUE(ranCleanly(out,
                         " --set 'study.dimensions=[2, 3]' --set 'study.methods=[\"rkcm\"]'"
                         " --set 'study.rk_orders=[2]' --set 'study.rk_support_ratios=[2.2, 2.5, 3.0]'"
                         " --set 'study.poisson_ratios=[0.25]' --set confirm.enabled=false"
                         " --set jitter.enabled=false",
                         "rk"));
  const auto atlas = table(out / "atlas.csv");
  EXPECT_EQ(find(atlas, {{"dimension", "2"}, {"value", "2.5"}}).at("status"), "ok");
  EXPECT_EQ(find(atlas, {{"dimension", "2"}, {"value", "3"}}).at("status"), "growing");
  EXPECT_EQ(find(atlas, {{"dimension", "3"}, {"value", "2.5"}}).at("status"), "growing");
  EXPECT_LT(std::stod(find(atlas, {{"dimension", "3"}, {"value", "2.5"}}).at("omega2_min_over_max")), -1);
}

TEST(StabilityAtlasStudy, BadInputNamesItsKey) {
  const fs::path out = fs::temp_directory_path() / "mfwave-atlas-bad";
  fs::remove_all(out);
  for (const auto& [sets, key] : std::vector<std::pair<std::string, std::string>>{
           {"--set 'confirm.integrators=[\"newmark\"]'", "confirm.integrators"},
           {"--set 'confirm.integrators=[\"arkode:heun_euler_2_1_2\"]'", "confirm.integrators"},
           {"--set 'study.poisson_ratios=[0.5]'", "study.poisson_ratios"},
           {"--set study.cells_2d=33", "study.cells_2d"},
           {"--set 'jitter.fractions=[0.5]'", "jitter.fractions"},
           {"--set 'jitter.methods=[\"finite_difference\"]'", "jitter.methods"}}) {
    const auto outcome = run("--out " + out.string() + " " + sets, "bad");
    EXPECT_EQ(outcome.exitCode, 2) << sets << '\n' << outcome.log;
    EXPECT_NE(outcome.log.find(key), std::string::npos) << outcome.log;
  }
  EXPECT_FALSE(fs::exists(out / "summary.json"));
}
