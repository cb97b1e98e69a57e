// Runs the lamb2d driver as a user would: the plane-strain Lamb problem (strip load) by very weak
// SPH against the exact Cagniard-de Hoop response at three receivers (the load centre, the surface
// 2 away, 1 below the centre). The errors are docs/studies/lamb2d.md's, the Galerkin variant
// converges at every receiver and the published scheme does not, and the Galerkin variant runs 50
// times the study's window at the study's finest default spacing with its energy only falling.
#include "support/StudyRun.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

namespace fs = std::filesystem;
using mfwave::testing::runStudy;
using mfwave::testing::summaryNumbers;

namespace {
mfwave::testing::StudyOutcome runLamb2d(const std::string& arguments, const std::string& name) {
  return runStudy(LAMB2D_EXECUTABLE, std::string(SCENES_FOLDER) + "/lamb2d.toml", arguments, "lamb2d-" + name);
}
}  // namespace

TEST(Lamb2dStudy, TheGalerkinVariantConvergesAtEveryReceiverAndThePublishedSchemeDoesNot) {
  const fs::path out = fs::temp_directory_path() / "mfwave-lamb2d-levels";
  fs::remove_all(out);
  const auto run = runLamb2d("--set 'study.spacings=[0.25,0.125,0.0625]' --set output.vtk=false --out " + out.string(),
                             "levels");
  ASSERT_TRUE(run.exited);
  ASSERT_EQ(run.exitCode, 0) << run.log;
  for (const char* file : {"cases.csv", "exact.csv", "galerkin_0.25-probes.csv", "published_0.0625-probes.csv"})
    EXPECT_TRUE(fs::exists(out / file)) << file;
  const auto e = summaryNumbers(out / "summary.json", "errors");
  // Measured (docs/studies/lamb2d.md).
  EXPECT_NEAR(e.at("galerkin_0.25_centre_relative_l2"), 0.079, 0.003);
  EXPECT_NEAR(e.at("galerkin_0.25_receiver_relative_l2"), 0.103, 0.004);
  EXPECT_NEAR(e.at("galerkin_0.25_buried_relative_l2"), 0.102, 0.004);
  EXPECT_NEAR(e.at("galerkin_0.0625_centre_relative_l2"), 0.0116, 0.001);
  EXPECT_NEAR(e.at("galerkin_0.0625_receiver_relative_l2"), 0.0284, 0.002);
  EXPECT_NEAR(e.at("galerkin_0.0625_buried_relative_l2"), 0.0214, 0.002);
  EXPECT_GT(e.at("published_0.0625_centre_relative_l2"), e.at("published_0.25_centre_relative_l2"));
  // Orders over two halvings: centre 1.4, receiver 0.93, buried 1.1 (the strip's edges are felt as
  // kinks in the exact response that a lattice resolves at first order).
  for (const char* receiver : {"centre", "receiver", "buried"}) {
    const double coarse = e.at(std::string("galerkin_0.25_") + receiver + "_relative_l2");
    const double fine = e.at(std::string("galerkin_0.0625_") + receiver + "_relative_l2");
    EXPECT_GT(std::log2(coarse / fine) / 2, 0.85) << receiver;
    // The published scheme (not consistent: docs/theory/very-weak-sph.md) does not converge: at
    // dx = 0.0625 it is no better than the zero signal (0.94, 1.00, 1.01 measured).
    EXPECT_GT(e.at(std::string("published_0.0625_") + receiver + "_relative_l2"), 0.8) << receiver;
  }
}

TEST(Lamb2dStudy, TheGalerkinVariantRunsFiftyWindowsAtTheFinestDefaultSpacingAndItsEnergyOnlyFalls) {
  const fs::path out = fs::temp_directory_path() / "mfwave-lamb2d-long";
  fs::remove_all(out);
  const auto run = runLamb2d("--set 'study.spacings=[0.0625]' --set geometry.spacing=0.0625 "
                             "--set study.compare_published=false --set output.vtk=false --set integrator.end_time=300 "
                             "--out " + out.string(),
                             "long");
  ASSERT_TRUE(run.exited);
  ASSERT_EQ(run.exitCode, 0) << run.log;  // the energy ledger stops (exit 3) on any growth after the load
  const auto f = summaryNumbers(out / "summary.json", "figures");
  EXPECT_LT(f.at("galerkin_0.0625_energy_final_fraction"), 1e-4);  // 5e-7 measured
  EXPECT_LT(f.at("galerkin_0.0625_energy_balance_drift"), 0.01);
  // The window's errors are those of the short run.
  const auto e = summaryNumbers(out / "summary.json", "errors");
  EXPECT_NEAR(e.at("galerkin_0.0625_centre_relative_l2"), 0.0116, 0.001);
}

TEST(Lamb2dStudy, AThreeDimensionalSceneIsRefusedNamingTheKey) {
  const fs::path out = fs::temp_directory_path() / "mfwave-lamb2d-3d";
  const auto run = runStudy(LAMB2D_EXECUTABLE, std::string(SCENES_FOLDER) + "/lamb3d.toml", "--out " + out.string(),
                            "lamb2d-3d");
  ASSERT_TRUE(run.exited);
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.log.find("scene.dimension"), std::string::npos) << run.log;
  EXPECT_NE(run.log.find("lamb2d is a 2-D study"), std::string::npos) << run.log;
}
