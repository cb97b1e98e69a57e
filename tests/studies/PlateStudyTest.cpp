// Runs the plate driver as a user would, at a coarse resolution (3 particles across the thickness,
// 99 particles, about 15 s): the Gray-Monaghan-Swift plate at V_f = 0.05 for 8 s (32 periods) with
// the scene's artificial terms, the small-amplitude case and the very weak form SPH beside it. Its
// outputs exist, and the period, the amplitude and the energy balance are what
// docs/studies/sph-solids.md reports, so a change to the method shows up here.
#include "support/StudyRun.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <string>

namespace fs = std::filesystem;
using mfwave::testing::runStudy;
using mfwave::testing::StudyOutcome;

namespace {

StudyOutcome runPlate(const std::string& arguments, const std::string& name) {
  return runStudy(PLATE_EXECUTABLE, std::string(SCENES_FOLDER) + "/plate.toml", arguments, "plate-" + name);
}

// errors and figures of summary.json in one map (null, i.e. NaN, entries are left out).
std::map<std::string, double> numbers(const fs::path& summaryPath) {
  return mfwave::testing::summaryNumbers(summaryPath);
}

}  // namespace

TEST(PlateStudy, CoarsePlateKeepsItsPeriodAmplitudeAndEnergyOverThirtyPeriods) {
  const fs::path out = fs::temp_directory_path() / "mfwave-plate-coarse";
  fs::remove_all(out);
  const StudyOutcome run = runPlate(
      "--set geometry.spacing=0.006666666666666667 --set 'study.resolutions=[3]' "
      "--set output.png=false --set output.every=40000 --out " +
          out.string(),
      "coarse");
  ASSERT_TRUE(run.exited && run.exitCode == 0) << run.log;
  for (const char* file : {"cases.csv", "ulsph_Hdp3_Vf0.05-tip.csv", "ulsph_Hdp3_Vf0.05-energy.csv",
                           "ulsph_Hdp3_Vf0.01-tip.csv", "vwsph_Hdp3_Vf0.01-tip.csv", "ulsph_Hdp3_Vf0.05.pvd",
                           "ulsph_Hdp3_Vf0.05_000001.vtp", "summary.json", "scene.resolved.toml"})
    EXPECT_TRUE(fs::exists(out / file)) << file;

  const auto v = numbers(out / "summary.json");
  const double thin = v.at("thin_period [s]"), timoshenko = v.at("timoshenko_period [s]");
  EXPECT_NEAR(thin, 0.25403, 1e-4);        // omega^2 = E H^2 k^4 / (12 rho (1 - nu^2)), kL = 1.8751
  EXPECT_NEAR(timoshenko, 0.25647, 1e-4);  // shear and rotary inertia: +0.96 %

  // The period, the mean over 32 periods of the large-amplitude case. Tolerance 10 % of the
  // Timoshenko period (docs/studies/sph-solids.md): shear and rotary inertia explain 1 %, the
  // amplitude 1 to 2 %, and at three particles across the SPH's own errors (free-surface kernel
  // deficiency, coarse lattice) partly cancel to -4 to -6 %. Not a claim about finer resolutions,
  // where the method is 12 to 25 % off. Measured: 0.2456 s, -4.2 %.
  EXPECT_NEAR(v.at("ulsph_Hdp3_Vf0.05_period_error_timoshenko"), 0.0, 0.10);
  EXPECT_NEAR(v.at("ulsph_Hdp3_Vf0.05_period [s]"), 0.2456, 0.005);  // regression: 2 %
  EXPECT_GE(v.at("ulsph_Hdp3_Vf0.05_periods_run"), 30.0);
  EXPECT_NEAR(v.at("ulsph_Hdp3_Vf0.01_period_error_timoshenko"), 0.0, 0.10);  // measured -6.4 %

  // The energy balance kinetic + internal - load work over 32 periods, relative to E(0): measured
  // 1.8e-5 (9.3e-6 at 5 particles across); bound 1e-4. The viscosity (alpha = 0.3) turns most of
  // the motion into heat meanwhile (0.81 of E(0)), which the balance counts.
  EXPECT_LT(v.at("ulsph_Hdp3_Vf0.05_energy_drift"), 1e-4);
  EXPECT_GT(v.at("ulsph_Hdp3_Vf0.05_viscous_fraction"), 0.5);
  EXPECT_LT(v.at("ulsph_Hdp3_Vf0.05_largest_zigzag_energy"), 0.01);  // measured 8.9e-4

  // The tip's first peak against v_tip(0) / omega (omega from the measured period): a mode started
  // with its own velocity reaches it exactly; measured 0.85 (V_f = 0.05) and 0.92 (V_f = 0.01), the
  // rest going into other modes and heat within the first quarter period.
  EXPECT_GT(v.at("ulsph_Hdp3_Vf0.05_first_amplitude_ratio"), 0.8);
  EXPECT_LT(v.at("ulsph_Hdp3_Vf0.05_first_amplitude_ratio"), 1.05);
  EXPECT_GT(v.at("ulsph_Hdp3_Vf0.01_first_amplitude_ratio"), 0.85);
  EXPECT_LT(v.at("ulsph_Hdp3_Vf0.01_first_amplitude_ratio"), 1.05);
  // And the amplitude scales with V_f: the ratio of the two first peaks is 5 within 10 %.
  EXPECT_NEAR(v.at("ulsph_Hdp3_Vf0.05_first_amplitude [m]") / v.at("ulsph_Hdp3_Vf0.01_first_amplitude [m]"), 5.0, 0.5);

  // The very weak form SPH on the same case (linear, small deformation): measured 0.2572 s, +0.3 %
  // against Timoshenko.
  EXPECT_NEAR(v.at("vwsph_Hdp3_Vf0.01_period_error_timoshenko"), 0.0, 0.03);
}

TEST(PlateStudy, BadInputNamesItsKeyAndWritesNothing) {
  const fs::path out = fs::temp_directory_path() / "mfwave-plate-bad";
  fs::remove_all(out);
  StudyOutcome run = runPlate("--set 'study.resolutions=[4.5]' --out " + out.string(), "bad-resolution");
  EXPECT_TRUE(run.exited);
  EXPECT_EQ(run.exitCode, 2) << run.log;
  EXPECT_NE(run.log.find("study.resolutions[0]"), std::string::npos) << run.log;
  run = runPlate("--set 'study.resolutions=[3, 0]' --out " + out.string(), "bad-zero");
  EXPECT_EQ(run.exitCode, 2) << run.log;
  EXPECT_NE(run.log.find("study.resolutions[1]"), std::string::npos) << run.log;
  run = runPlate("--set study.clamp_layers=1 --out " + out.string(), "bad-clamp");
  EXPECT_EQ(run.exitCode, 2) << run.log;
  EXPECT_NE(run.log.find("study.clamp_layers"), std::string::npos) << run.log;
  run = runPlate("--set method.name=finite_difference --out " + out.string(), "bad-method");
  EXPECT_EQ(run.exitCode, 2) << run.log;
  EXPECT_NE(run.log.find("method.name"), std::string::npos) << run.log;
  EXPECT_FALSE(fs::exists(out / "summary.json"));
  EXPECT_FALSE(fs::exists(out / "cases.csv"));
}
