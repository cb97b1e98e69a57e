// Runs the bar1d and plane2d drivers (Luo-Liu-Huang RK collocation) as a user would and checks
// their convergence tables, and that an unstable support is refused.
#include "support/StudyRun.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

namespace {

using RkcmRow = std::vector<std::string>;

std::vector<RkcmRow> readCsv(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  std::vector<RkcmRow> rows;
  while (std::getline(in, line)) {
    std::stringstream s(line);
    RkcmRow r;
    std::string f;
    while (std::getline(s, f, ',')) r.push_back(f);
    rows.push_back(r);
  }
  return rows;
}

std::string scratch(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("mfwave-study-" + name);
  std::filesystem::remove_all(dir);
  return dir.string();
}

double num(const RkcmRow& r, std::size_t i) { return std::stod(r.at(i)); }

}  // namespace

// Columns: nodes,h,dt,critical_dt,steps,relative_l2_u,order_u,relative_l2_v,order_v,max_t,wall
TEST(Bar1dStudy, DisplacementConvergesAtFirstOrderVelocityAtAboutOneThird) {
  const std::string out = scratch("bar1d");
  const std::string command = std::string(BAR1D_EXECUTABLE) + " --quiet --scene " + SCENES_FOLDER +
                              "/bar1d.toml --out " + out + " --set 'study.nodes=[21, 41, 81, 161]' > " + out +
                              ".log 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  const auto rows = readCsv(out + "/convergence.csv");
  ASSERT_EQ(rows.size(), 4u);
  // The paper's case (Ns = 21, a = 3.3 h): measured 2.88e-2 (u) and 0.273 (v) at T = 5.
  EXPECT_NEAR(num(rows[0], 5), 2.88e-2, 2e-3);
  // The exact velocity jumps and u has kinks: for a non-dissipative second-order scheme the L2
  // error of step data decays like h^(1/3) and of its integral like h^1 (Brenner-Thomee-Wahlbin).
  // Measured orders on the last halving: u 0.96, v 0.31.
  EXPECT_NEAR(num(rows[3], 6), 1.0, 0.1);
  EXPECT_NEAR(num(rows[3], 8), 1.0 / 3, 0.1);
  // Critical step of the paper's case: c dt = 0.3106 (paper, Table 1: 0.318 predicted, 0.322 numerical).
  EXPECT_NEAR(num(rows[0], 3) * std::sqrt(10.0), 0.3106, 2e-3);
  EXPECT_TRUE(std::filesystem::exists(out + "/nodes-161-profile.csv"));
  EXPECT_EQ(mfwave::testing::summaryDisagreements(out), std::vector<std::string>{});  // every output listed
}

TEST(Bar1dStudy, ImplicitNewmarkAgreesWithCentralDifference) {
  const std::string out = scratch("bar1d-newmark");
  const std::string command = std::string(BAR1D_EXECUTABLE) + " --quiet --scene " + SCENES_FOLDER +
                              "/bar1d.toml --out " + out +
                              " --set 'study.nodes=[41]' --set integrator.name=newmark --set integrator.cfl=0.5 > " +
                              out + ".log 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  const auto rows = readCsv(out + "/convergence.csv");
  ASSERT_EQ(rows.size(), 1u);
  // Central difference gives 1.58e-2 for 41 nodes; average acceleration has a different (larger)
  // dispersion error at the same step but the same size.
  EXPECT_LT(num(rows[0], 5), 3e-2);
  EXPECT_GT(num(rows[0], 5), 5e-3);
}

// Columns: cells,h,dt,critical_dt,steps,relative_l2_u,order_u,relative_l2_v,order_v,wall
TEST(Plane2dStudy, PlaneStrainConvergesAtSecondOrderInL2) {
  const std::string out = scratch("plane2d");
  const std::string command = std::string(PLANE2D_EXECUTABLE) + " --quiet --scene " + SCENES_FOLDER +
                              "/plane2d.toml --out " + out + " --set 'study.cells=[8, 16, 32]' > " + out +
                              ".log 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  const auto rows = readCsv(out + "/convergence.csv");
  ASSERT_EQ(rows.size(), 3u);
  // m = 2 (even) collocation: O(h^2) in L2 (central difference at a fixed fraction of the
  // critical step adds O(dt^2) = O(h^2)). Measured 1.72 and 1.91 for u, 1.7 and 1.9 for v;
  // pre-asymptotic from below.
  EXPECT_NEAR(num(rows[2], 6), 2.0, 0.2);
  EXPECT_NEAR(num(rows[2], 8), 2.0, 0.2);
  EXPECT_LT(num(rows[2], 5), 6e-3);
  EXPECT_EQ(mfwave::testing::summaryDisagreements(out), std::vector<std::string>{});  // every output listed
}

// Issue 17: RK collocation at a / h = 3 in 2-D has interior modes with omega^2 < 0 (they grow at
// every step; the run used to end with exit 0 and an error of 1e121). The driver now refuses it
// before stepping, with exit 3 naming the key, the wavenumber and the size; no summary is written.
// stability.allow_growth runs it anyway and says so in the summary.
TEST(Plane2dStudy, GrowingInteriorModesAreRefusedBeforeStepping) {
  const std::string out = scratch("plane2d-unstable");
  const std::string base = std::string(PLANE2D_EXECUTABLE) + " --quiet --scene " + SCENES_FOLDER +
                           "/plane2d.toml --out " + out + " --set 'study.cells=[8]' --set method.support_ratio=3.0 ";
  const int refused = std::system((base + "> " + out + ".log 2>&1").c_str());
  ASSERT_TRUE(WIFEXITED(refused));
  EXPECT_EQ(WEXITSTATUS(refused), 3);
  std::ifstream log(out + ".log");
  const std::string text((std::istreambuf_iterator<char>(log)), std::istreambuf_iterator<char>());
  for (const char* part : {"growing modes", "method.support_ratio = 3", "omega^2 reaches -0.23", "k dx = (2.7",
                           "refused before stepping", "stability.allow_growth"})
    EXPECT_NE(text.find(part), std::string::npos) << part << " missing in: " << text;
  EXPECT_FALSE(std::filesystem::exists(out + "/summary.json"));

  const int allowed = std::system((base + "--set stability.allow_growth=true > " + out + "-allowed.log 2>&1").c_str());
  ASSERT_TRUE(WIFEXITED(allowed));
  EXPECT_EQ(WEXITSTATUS(allowed), 0);
  std::ifstream summary(out + "/summary.json");
  const std::string json((std::istreambuf_iterator<char>(summary)), std::istreambuf_iterator<char>());
  EXPECT_NE(json.find("stability.allow_growth: ran although"), std::string::npos) << json;
}

namespace {

struct Bar1dRun {
  int exitCode;
  std::string log;
};

Bar1dRun runBar1d(const std::string& sets, const std::string& name,
             const std::string& scene = std::string(SCENES_FOLDER) + "/bar1d.toml") {
  const std::string out = scratch("bar1d-" + name);
  const std::string command = std::string(BAR1D_EXECUTABLE) + " --quiet --scene " + scene + " --out " + out + " " +
                              sets + " > " + out + ".log 2>&1";
  const int status = std::system(command.c_str());
  std::ifstream in(out + ".log");
  return {WEXITSTATUS(status), std::string(std::istreambuf_iterator<char>(in), {})};
}

}  // namespace

// Before stepping, bar1d takes the whole collocation operator's spectrum: a step above the
// integrator's limit is refused (exit 2, naming integrator.cfl), growing modes are refused (exit
// 3): RK at a / h = 6, and radial-basis collocation at its defaults, whose complex pair grows
// faster the more nodes there are (the "worse with more nodes" of the RBCM path).
TEST(Bar1dStudy, UnstableStepsAndOperatorsAreRefusedBeforeStepping) {
  const Bar1dRun step = runBar1d("--set 'study.nodes=[21]' --set integrator.cfl=5", "cfl");
  EXPECT_EQ(step.exitCode, 2) << step.log;
  EXPECT_NE(step.log.find("integrator.cfl: the step"), std::string::npos) << step.log;
  const Bar1dRun newmark = runBar1d("--set 'study.nodes=[21]' --set integrator.name=newmark "
                               "--set integrator.newmark_beta=0.1 --set integrator.cfl=1.5", "newmark");
  EXPECT_EQ(newmark.exitCode, 2) << newmark.log;
  EXPECT_NE(newmark.log.find("newmark limit 2.58199"), std::string::npos) << newmark.log;
  const Bar1dRun wide = runBar1d("--set 'study.nodes=[21]' --set method.support_ratio=6", "wide");
  EXPECT_EQ(wide.exitCode, 3) << wide.log;
  EXPECT_NE(wide.log.find("growing modes"), std::string::npos) << wide.log;
  EXPECT_NE(wide.log.find("method.support_ratio = 6"), std::string::npos) << wide.log;
  // Radial basis (inverse multiquadric, a_r = h): measured growth rates 3.12, 6.25 and 12.5 1/s at
  // 21, 41 and 81 nodes. The scene without the RK keys, which radial_basis refuses.
  std::ifstream in(std::string(SCENES_FOLDER) + "/bar1d.toml");
  std::string text((std::istreambuf_iterator<char>(in)), {});
  for (const std::string line : {"order = 2\n", "support_ratio = 3.3\n"}) text.erase(text.find(line), line.size());
  const std::string rk = "name = \"reproducing_kernel\"";
  text.replace(text.find(rk), rk.size(), "name = \"radial_basis\"");
  const std::string scene = scratch("bar1d-rb-scene") + ".toml";
  std::ofstream(scene) << text;
  double previous = 0;
  for (int nodes : {21, 41}) {
    const Bar1dRun basis = runBar1d("--set 'study.nodes=[" + std::to_string(nodes) + "]'", "rb" + std::to_string(nodes),
                               scene);
    ASSERT_EQ(basis.exitCode, 3) << basis.log;
    const auto at = basis.log.find("growth rate ");
    ASSERT_NE(at, std::string::npos) << basis.log;
    const double rate = std::stod(basis.log.substr(at + 12));
    EXPECT_GT(rate, 1.8 * previous) << basis.log;
    previous = rate;
  }
  EXPECT_NEAR(previous, 6.25, 0.1);
  // Run on purpose (stability.allow_growth) at 41 nodes, the stability monitor sees the slow
  // growth after the impact (no load acts from t = 0): displacement and velocity both 1000 times
  // their largest values over the first 50 steps (t = 1.25) by t = 1.25 + ln(1000) / 6.25 = 2.35,
  // and the summary says so.
  const Bar1dRun allowed = runBar1d("--set 'study.nodes=[41]' --set stability.allow_growth=true", "rb-allowed", scene);
  ASSERT_EQ(allowed.exitCode, 0) << allowed.log;
  std::ifstream summary(std::filesystem::temp_directory_path() / "mfwave-study-bar1d-rb-allowed" / "summary.json");
  const std::string json((std::istreambuf_iterator<char>(summary)), {});
  const auto at = json.find("growth after the loads ended");
  ASSERT_NE(at, std::string::npos) << json;
  const auto time = json.rfind("t = ", at);
  ASSERT_NE(time, std::string::npos) << json;
  EXPECT_NEAR(std::stod(json.substr(time + 4)), 2.35, 0.1) << json;
}
