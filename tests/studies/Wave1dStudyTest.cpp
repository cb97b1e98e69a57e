// Runs the wave1d driver as a user would and checks its convergence table against theory.
#include "support/StudyRun.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

const std::string SCENE = std::string(SCENES_FOLDER) + "/wave1d.toml";

struct Row {
  std::string integrator;
  int cells;
  double error, order, energyDrift;
};

std::vector<Row> readTable(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);  // header
  std::vector<Row> rows;
  while (std::getline(in, line)) {
    std::stringstream s(line);
    std::vector<std::string> f;
    std::string field;
    while (std::getline(s, field, ',')) f.push_back(field);
    rows.push_back({f.at(0), std::stoi(f.at(1)), std::stod(f.at(5)), std::stod(f.at(6)), std::stod(f.at(7))});
  }
  return rows;
}

std::string scratchFolder(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("mfwave-study-" + name);
  std::filesystem::remove_all(dir);
  return dir.string();
}

}  // namespace

TEST(Wave1dStudy, EveryIntegratorConvergesAtSecondOrderInDx) {
  const std::string out = scratchFolder("wave1d");
  const std::string command = std::string(WAVE1D_EXECUTABLE) + " --quiet --scene " + SCENE + " --out " + out +
                              " --set 'study.cells=[16, 32, 64, 128]' > " + out + ".log 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  const std::vector<Row> rows = readTable(out + "/convergence.csv");
  ASSERT_EQ(rows.size(), 16u);
  std::map<std::string, std::vector<Row>> byIntegrator;
  for (const Row& r : rows) byIntegrator[r.integrator].push_back(r);
  for (const auto& [name, series] : byIntegrator) {
    // Finest pair: the FD Laplacian and every integrator here are second order (RK4 is fourth
    // order in time but the space error O(dx^2) dominates at a fixed CFL number).
    EXPECT_NEAR(series.back().order, 2.0, 0.1) << name;
    EXPECT_LT(series.back().error, 1e-3) << name;
    // The bar is undamped: the symplectic and energy-conserving schemes keep E within O(dt^2),
    // the explicit Runge-Kutta scheme loses a little.
    EXPECT_LT(series.back().energyDrift, 1e-2) << name;
  }
  EXPECT_TRUE(std::filesystem::exists(out + "/central_difference-128-probe.csv"));
  EXPECT_EQ(mfwave::testing::summaryDisagreements(out), std::vector<std::string>{});  // every output listed
}

TEST(Wave1dStudy, BadInputFailsWithTheKeyAndNoOutput) {
  const std::string out = scratchFolder("wave1d-bad");
  const std::string command = std::string(WAVE1D_EXECUTABLE) + " --quiet --scene " + SCENE +
                              " --set integrator.cfl=-1 --out " + out + " > " + out + ".log 2>&1";
  const int status = std::system(command.c_str());
  EXPECT_NE(status, 0);
  std::ifstream log(out + ".log");
  std::stringstream text;
  text << log.rdbuf();
  EXPECT_NE(text.str().find("integrator.cfl: must be positive"), std::string::npos) << text.str();
  EXPECT_EQ(WEXITSTATUS(status), 2);
  EXPECT_FALSE(std::filesystem::exists(out + "/convergence.csv"));
}

TEST(Wave1dStudy, AnUnstableStepIsStoppedWithWhereAndWhen) {
  // c dt / dx = 1.05 is above the central-difference limit of 1 for this operator; run there on
  // purpose (stability.allow_growth), the monitor stops the blow-up.
  const std::string out = scratchFolder("wave1d-unstable");
  const std::string command = std::string(WAVE1D_EXECUTABLE) + " --quiet --scene " + SCENE +
                              " --set integrator.cfl=1.05 --set stability.allow_growth=true --set 'study.cells=[64]' --set " +
                              "'study.integrators=[\"central_difference\"]' --set integrator.end_time=20 --out " + out +
                              " > " + out + ".log 2>&1";
  const int status = std::system(command.c_str());
  EXPECT_EQ(WEXITSTATUS(status), 3);
  std::ifstream log(out + ".log");
  std::stringstream text;
  text << log.rdbuf();
  EXPECT_NE(text.str().find("instability at step"), std::string::npos) << text.str();
  EXPECT_NE(text.str().find("particle"), std::string::npos) << text.str();
}

// Issue 17: a short run at 1.2 x the stable step used to end with exit 0 (the blow-up had no time to
// show). The step is now refused before any work, naming the key and the limit (exit 2, no output);
// with stability.allow_growth the run goes on and its summary says so.
// Every integrator's own limit is checked before any work (integrators/StabilityLimit): classic
// RK4 above 2 sqrt 2 / omega_max, an ERK table and a Newmark gamma that grow at any step.
TEST(Wave1dStudy, EveryIntegratorsLimitIsCheckedBeforeAnyWork) {
  const std::string out = scratchFolder("wave1d-integrator-limits");
  const std::string base = std::string(WAVE1D_EXECUTABLE) + " --quiet --scene " + SCENE +
                           " --set integrator.end_time=0.2 --set 'study.cells=[32]' --out " + out;
  struct Case {
    std::string sets;
    std::vector<std::string> parts;
  };
  const std::vector<Case> cases = {
      {" --set 'study.integrators=[\"arkode\"]' --set integrator.name=arkode --set integrator.cfl=2",
       {"integrator.cfl", "arkode:classic_rk4 limit 2.82843", "cfl <= 1.41421"}},
      {" --set 'study.integrators=[\"arkode\"]' --set integrator.name=arkode --set "
       "integrator.arkode_table=heun_euler_2_1_2",
       {"integrator.arkode_table", "grow at any step"}},
      {" --set 'study.integrators=[\"newmark\"]' --set integrator.name=newmark --set integrator.newmark_gamma=0.3",
       {"integrator.newmark_gamma", "newmark_gamma >= 0.5"}},
      {" --set 'study.integrators=[\"newmark\"]' --set integrator.name=newmark --set integrator.newmark_beta=0.1 "
       "--set integrator.cfl=2",
       {"integrator.cfl", "newmark limit 2.58199"}}};
  for (const Case& c : cases) {
    const int status = std::system((base + c.sets + " > " + out + ".log 2>&1").c_str());
    EXPECT_EQ(WEXITSTATUS(status), 2) << c.sets;
    std::ifstream log(out + ".log");
    std::stringstream text;
    text << log.rdbuf();
    for (const std::string& part : c.parts)
      EXPECT_NE(text.str().find(part), std::string::npos) << part << " missing in: " << text.str();
  }
  // Classic RK4 just inside its limit (1.4 of the central-difference step) runs.
  const int inside = std::system((base + " --set 'study.integrators=[\"arkode\"]' --set integrator.name=arkode "
                                         "--set integrator.cfl=1.4 > " + out + ".log 2>&1").c_str());
  EXPECT_EQ(WEXITSTATUS(inside), 0);
}

TEST(Wave1dStudy, AStepAboveTheLimitIsRefusedBeforeAnyWork) {
  const std::string out = scratchFolder("wave1d-above-limit");
  const std::string base = std::string(WAVE1D_EXECUTABLE) + " --quiet --scene " + SCENE +
                           " --set integrator.cfl=1.2 --set integrator.end_time=0.2 --set 'study.cells=[32]' --set " +
                           "'study.integrators=[\"central_difference\"]' --out " + out;
  const int refused = std::system((base + " > " + out + ".log 2>&1").c_str());
  EXPECT_EQ(WEXITSTATUS(refused), 2);
  std::ifstream log(out + ".log");
  std::stringstream text;
  text << log.rdbuf();
  for (const char* part : {"integrator.cfl", "exceeds the central_difference limit 2 / omega_max = 0.03125", "cfl <= 1"})
    EXPECT_NE(text.str().find(part), std::string::npos) << part << " missing in: " << text.str();
  EXPECT_FALSE(std::filesystem::exists(out + "/summary.json"));

  const int allowed = std::system((base + " --set stability.allow_growth=true > " + out + ".log 2>&1").c_str());
  EXPECT_EQ(WEXITSTATUS(allowed), 0);
  std::ifstream summary(out + "/summary.json");
  std::stringstream json;
  json << summary.rdbuf();
  EXPECT_NE(json.str().find("stability.allow_growth: ran although the step"), std::string::npos) << json.str();
}
