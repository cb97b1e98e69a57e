// Runs the bar1d-sph driver as a user would (two bars meeting at +-v0, updated-Lagrangian SPH) on
// three spacings, and checks what docs/studies/sph-solids.md reports: the plateau stress -rho c v0,
// the fronts at +-c t, L1 errors converging at the order a smeared jump allows, and the energy balance.
#include "support/StudyRun.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using mfwave::testing::runStudy;
using mfwave::testing::StudyOutcome;
using mfwave::testing::summaryFiles;
using mfwave::testing::summaryNumbers;

namespace {

StudyOutcome runBar(const std::string& arguments, const std::string& name) {
  return runStudy(BAR1D_SPH_EXECUTABLE, std::string(SCENES_FOLDER) + "/bar1d-sph.toml", arguments, "bar1d-sph-" + name);
}

}  // namespace

TEST(Bar1dSphStudy, PlateauFrontsAndConvergence) {
  const fs::path out = fs::temp_directory_path() / "mfwave-bar1d-sph";
  fs::remove_all(out);
  const StudyOutcome run = runBar("--set 'study.spacings=[0.02,0.01,0.005]' --set geometry.spacing=0.01 --out " + out.string(),
                             "three");
  ASSERT_TRUE(run.exited && run.exitCode == 0) << run.log;
  EXPECT_EQ(mfwave::testing::summaryDisagreements(out), std::vector<std::string>{});  // every output listed
  for (const char* file : {"cases.csv", "profile-0.02.csv", "profile-0.01.csv", "profile-0.005.csv", "frame.pvd",
                           "summary.json", "scene.resolved.toml"})
    EXPECT_TRUE(fs::exists(out / file)) << file;
  // The frame series of the middle case (dx = geometry.spacing) is listed with what it holds.
  const std::vector<std::string> listed = summaryFiles(out / "summary.json");
  EXPECT_TRUE(std::any_of(listed.begin(), listed.end(), [](const std::string& f) { return f.rfind("frame.pvd (", 0) == 0; }));

  const auto e = summaryNumbers(out / "summary.json", "errors");
  const auto f = summaryNumbers(out / "summary.json", "figures");
  // Measured at dx = 0.005 (h = 2 dx, v0 / c = 0.1 %): the plateau within 0.03 % of -rho c v0, the
  // front 0.83 dx behind c t (the smeared front's midpoint; -0.76 dx at 0.01), L1 errors 0.071.
  EXPECT_LT(std::abs(e.at("plateau_stress_error_finest")), 0.002);
  EXPECT_LT(std::abs(e.at("front_error_over_dx_finest")), 1.5);
  EXPECT_NEAR(e.at("l1_velocity_finest"), 0.071, 0.005);
  EXPECT_NEAR(e.at("l1_stress_finest"), 0.071, 0.005);
  // A jump smeared by viscosity and dispersion: L1 orders between 1/2 (diffusive width sqrt(h t))
  // and 2/3 (dispersive width (h^2 t)^(1/3)); measured 0.59 and 0.60.
  EXPECT_GT(f.at("order_l1_velocity"), 0.5);
  EXPECT_LT(f.at("order_l1_velocity"), 0.7);
  EXPECT_GT(f.at("order_l1_stress"), 0.5);
  EXPECT_LT(f.at("order_l1_stress"), 0.7);
  // kinetic + internal drifts by 2.3e-5 of the initial energy at dx = 0.005, halving with dx.
  EXPECT_LT(f.at("balance_drift_finest"), 1e-4);
}

TEST(Bar1dSphStudy, EndTimeAfterTheFrontsReachTheEndsIsRefused) {
  const fs::path out = fs::temp_directory_path() / "mfwave-bar1d-sph-late";
  fs::remove_all(out);
  const StudyOutcome run = runBar("--set integrator.end_time=1.5 --out " + out.string(), "late");
  ASSERT_TRUE(run.exited);
  EXPECT_NE(run.exitCode, 0);
  EXPECT_NE(run.log.find("integrator.end_time"), std::string::npos) << run.log;
  EXPECT_FALSE(fs::exists(out / "cases.csv"));
}
