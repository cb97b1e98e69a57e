// Runs the plate driver as a user would, at coarse resolutions (about 70 s on one core): the
// Gray-Monaghan-Swift plate at V_f = 0.05 for 13 s (31 periods) at 3 particles across the
// thickness with the scene's kernel-gradient correction and artificial terms, the small amplitude
// at 3, 4 and 5 across, and the very weak form and total-Lagrangian SPH beside it. Its outputs
// exist, and the periods, their convergence, the amplitude and the energy balance are what
// docs/studies/sph-solids.md reports, so a change to the method shows up here.
#include "support/StudyRun.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <vector>

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

TEST(PlateStudy, CoarsePlatesConvergeAndKeepTheirEnergyOverThirtyPeriods) {
  const fs::path out = fs::temp_directory_path() / "mfwave-plate-coarse";
  fs::remove_all(out);
  const StudyOutcome run = runPlate(
      "--set geometry.spacing=0.006666666666666667 --set integrator.end_time=13 "
      "--set 'study.resolutions=[3, 4, 5]' --set study.convergence_end_time=0.7 "
      "--set output.png=false --set output.every=40000 --out " +
          out.string(),
      "coarse");
  ASSERT_TRUE(run.exited && run.exitCode == 0) << run.log;
  EXPECT_EQ(mfwave::testing::summaryDisagreements(out), std::vector<std::string>{});  // every output listed
  for (const char* file : {"cases.csv", "ulsph_Hdp3_Vf0.05-tip.csv", "ulsph_Hdp3_Vf0.05-energy.csv",
                           "ulsph_Hdp3_Vf0.01-tip.csv", "ulsph_Hdp5_Vf0.01-tip.csv", "vwsph_Hdp3_Vf0.01-tip.csv",
                           "ulsph_Hdp3_Vf0.05.pvd", "ulsph_Hdp3_Vf0.05_000001.vtp", "summary.json",
                           "scene.resolved.toml"})
    EXPECT_TRUE(fs::exists(out / file)) << file;

  const auto v = numbers(out / "summary.json");
  const double thin = v.at("thin_period [s]"), timoshenko = v.at("timoshenko_period [s]");
  EXPECT_NEAR(thin, 0.25403, 1e-4);        // omega^2 = E H^2 k^4 / (12 rho (1 - nu^2)), kL = 1.8751
  EXPECT_NEAR(timoshenko, 0.25647, 1e-4);  // shear and rotary inertia: +0.96 %

  // The small-amplitude periods fall towards the reference as particles are added: measured
  // 0.4452, 0.3554 and 0.3227 s at 3, 4 and 5 across (regression: 1 %). At these coarse
  // resolutions the observed order is 2.9 and the Richardson limit +11.9 % from Timoshenko; the
  // default study's 5, 7, 10 give order 1.9 and +2.5 % (docs/studies/sph-solids.md).
  EXPECT_NEAR(v.at("ulsph_Hdp3_Vf0.01_period [s]"), 0.4452, 0.0045);
  EXPECT_NEAR(v.at("ulsph_Hdp4_Vf0.01_period [s]"), 0.3554, 0.0036);
  EXPECT_NEAR(v.at("ulsph_Hdp5_Vf0.01_period [s]"), 0.3227, 0.0032);
  EXPECT_GT(v.at("ulsph_period_order"), 1.5);
  EXPECT_LT(v.at("ulsph_period_order"), 3.5);
  EXPECT_GT(v.at("ulsph_extrapolated_period_error_timoshenko"), 0.0);
  EXPECT_LT(v.at("ulsph_extrapolated_period_error_timoshenko"), 0.15);
  // The same resolutions linearised about rest: 0.42491, 0.34107, 0.31116 s (deterministic).
  EXPECT_NEAR(v.at("linearised_Hdp3_period [s]"), 0.42491, 1e-4);
  EXPECT_NEAR(v.at("linearised_Hdp5_period [s]"), 0.31116, 1e-4);

  // The large amplitude over 31 periods: the period hardly moves (single periods 0.4234 to
  // 0.4243 s; the mean 0.4241 s, 4.7 % shorter than at V_f = 0.01).
  EXPECT_GE(v.at("ulsph_Hdp3_Vf0.05_periods_run"), 30.0);
  EXPECT_NEAR(v.at("ulsph_Hdp3_Vf0.05_period [s]"), 0.4241, 0.0042);
  EXPECT_LT(v.at("ulsph_Hdp3_Vf0.05_longest_period [s]") / v.at("ulsph_Hdp3_Vf0.05_shortest_period [s]"), 1.01);

  // The energy balance kinetic + internal - load work over 31 periods, relative to E(0): measured
  // 5.9e-5 (9.5e-6 at 5 particles across); bound 2e-4. The viscosity (alpha = 0.3) takes 7 % of
  // E(0) meanwhile, which the balance counts; the particle-scale kinetic energy stays small.
  EXPECT_LT(v.at("ulsph_Hdp3_Vf0.05_energy_drift"), 2e-4);
  EXPECT_GT(v.at("ulsph_Hdp3_Vf0.05_viscous_fraction"), 0.02);
  EXPECT_LT(v.at("ulsph_Hdp3_Vf0.05_viscous_fraction"), 0.2);
  EXPECT_LT(v.at("ulsph_Hdp3_Vf0.05_largest_zigzag_energy"), 0.01);  // measured 8.3e-4

  // The tip's first peak against v_tip(0) / omega (omega from the measured period): a mode started
  // with its own velocity reaches it exactly; measured 0.81 (V_f = 0.05) and 0.98 (V_f = 0.01), the
  // rest going into other modes within the first quarter period.
  EXPECT_GT(v.at("ulsph_Hdp3_Vf0.05_first_amplitude_ratio"), 0.75);
  EXPECT_LT(v.at("ulsph_Hdp3_Vf0.05_first_amplitude_ratio"), 1.05);
  EXPECT_GT(v.at("ulsph_Hdp3_Vf0.01_first_amplitude_ratio"), 0.9);
  EXPECT_LT(v.at("ulsph_Hdp3_Vf0.01_first_amplitude_ratio"), 1.05);

  // The very weak form SPH on the same case (linear, small deformation): measured 0.2572 s, +0.3 %
  // against Timoshenko.
  EXPECT_NEAR(v.at("vwsph_Hdp3_Vf0.01_period_error_timoshenko"), 0.0, 0.03);

  // The total-Lagrangian SPH on the same particles: 0.22635, 0.23763 and 0.24364 s at 3, 4 and 5
  // across (regression: 1 %), from below; Richardson limit +1.1 % from Timoshenko. Its V_f = 0.05
  // case runs 57 periods in the 13 s with no artificial terms: the energy (kinetic + strain +
  // penalty) moves by 8.1e-5 of E(0) at most and the last amplitude is 0.9995 of the first.
  EXPECT_NEAR(v.at("tlsph_Hdp3_Vf0.01_period [s]"), 0.22635, 0.0023);
  EXPECT_NEAR(v.at("tlsph_Hdp4_Vf0.01_period [s]"), 0.23763, 0.0024);
  EXPECT_NEAR(v.at("tlsph_Hdp5_Vf0.01_period [s]"), 0.24364, 0.0024);
  EXPECT_NEAR(v.at("tlsph_extrapolated_period_error_timoshenko"), 0.0, 0.03);
  EXPECT_GE(v.at("tlsph_Hdp3_Vf0.05_periods_run"), 50.0);
  EXPECT_LT(v.at("tlsph_Hdp3_Vf0.05_energy_drift"), 1e-3);
  EXPECT_GT(v.at("tlsph_Hdp3_Vf0.05_last_amplitude_ratio"), 0.99);
}

TEST(PlateStudy, LinearisedPeriodConvergesToTimoshenkoAtSecondOrder) {
  // The discretisation alone (study.linearised_modes: small vibrations about rest, no amplitude,
  // no artificial terms, no time integration) at 5, 7 and 10 particles across: measured 0.31116,
  // 0.28489 and 0.27107 s, observed order 2.03, Richardson limit 0.25808 s, +0.63 % from the
  // Timoshenko period (with 14 across: order 1.89, +0.11 %). The runs are cut to 0.01 s here.
  const fs::path out = fs::temp_directory_path() / "mfwave-plate-modes";
  fs::remove_all(out);
  const StudyOutcome run = runPlate(
      "--set 'study.resolutions=[5, 7, 10]' --set integrator.end_time=0.01 --set study.convergence_end_time=0.01 "
      "--set study.very_weak_sph=false --set output.vtk=false --set output.png=false --out " +
          out.string(),
      "modes");
  ASSERT_TRUE(run.exited && run.exitCode == 0) << run.log;
  EXPECT_EQ(mfwave::testing::summaryDisagreements(out), std::vector<std::string>{});  // every output listed
  EXPECT_TRUE(fs::exists(out / "modes.csv"));
  // summary.json lists every file the run wrote, modes.csv included.
  std::ifstream json(out / "summary.json");
  const std::string text((std::istreambuf_iterator<char>(json)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("\"modes.csv\""), std::string::npos) << text;
  EXPECT_NE(text.find("\"cases.csv\""), std::string::npos) << text;
  const auto v = numbers(out / "summary.json");
  EXPECT_NEAR(v.at("linearised_Hdp5_period [s]"), 0.31116, 1e-4);
  EXPECT_NEAR(v.at("linearised_Hdp7_period [s]"), 0.28489, 1e-4);
  EXPECT_NEAR(v.at("linearised_Hdp10_period [s]"), 0.27107, 1e-4);
  EXPECT_EQ(v.at("linearised_Hdp10_growth_rate [1/s]"), 0.0);  // no unstable or flutter mode
  EXPECT_GT(v.at("linearised_period_order"), 1.7);
  EXPECT_LT(v.at("linearised_period_order"), 2.3);
  // The acceptance tolerance of the plate study: the limit within 1.5 % of Timoshenko (shear and
  // rotary inertia are in the reference; what remains is the extrapolation from three resolutions).
  EXPECT_NEAR(v.at("linearised_extrapolated_period_error_timoshenko"), 0.0, 0.015);
}

TEST(PlateStudy, TheTotalLagrangianPlateIsWithinThreePercentAtSevenAcross) {
  // The total-Lagrangian SPH (reference kernels with the correction, Saint Venant-Kirchhoff, the
  // hourglass penalty at Young's modulus, no artificial terms) at the small amplitude: measured
  // 0.24365, 0.24954 and 0.25287 s at 5, 7 and 10 across, -4.5, -2.2 and -0.9 % from the converged
  // plane-strain value 0.2552 s, converging from below at second order where the updated-Lagrangian
  // SPH converges from above (+26, +15, +9.4 %). The cheaper case of the study's claim (within 3 %
  // at ten across): seven across, one period and a fifth.
  const fs::path out = fs::temp_directory_path() / "mfwave-plate-tlsph";
  fs::remove_all(out);
  const StudyOutcome run = runPlate(
      "--set geometry.spacing=0.002857142857142857 --set 'study.resolutions=[7]' --set integrator.end_time=0.3 "
      "--set study.velocity_factor=0.01 --set study.small_velocity_factor=0 --set study.linearised_modes=false "
      "--set study.very_weak_sph=false --set output.vtk=false --set output.png=false --out " +
          out.string(),
      "tlsph");
  ASSERT_TRUE(run.exited && run.exitCode == 0) << run.log;
  EXPECT_TRUE(fs::exists(out / "tlsph_Hdp7_Vf0.01-tip.csv"));
  const auto v = numbers(out / "summary.json");
  const double period = v.at("tlsph_Hdp7_Vf0.01_period [s]");
  EXPECT_NEAR(period, 0.24954, 0.0025);  // regression: 1 %
  EXPECT_LT(std::abs(period / 0.2552 - 1), 0.03);
  EXPECT_LT(std::abs(v.at("tlsph_Hdp7_Vf0.01_period_error_timoshenko")), 0.03);
  // No artificial terms: the energy (kinetic + strain + penalty) only breathes with the step.
  EXPECT_LT(v.at("tlsph_Hdp7_Vf0.01_energy_drift"), 1e-3);
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

TEST(PlateStudy, ABlowUpStopsAtOnceAndSaysWhereAndWhen) {
  // Without viscosity the artificial stress (epsilon = 0.3) drives the coarse plate unstable
  // (measured: at step 41600, t = 1.66 s, the balance has moved by all of E(0)). The energy ledger
  // stops the run there with exit code 3 and a message naming step, time and particle; no summary
  // or case table is written. The frames before the blow-up stay, for a look at where it started.
  const fs::path out = fs::temp_directory_path() / "mfwave-plate-blowup";
  fs::remove_all(out);
  const StudyOutcome run = runPlate(
      "--set geometry.spacing=0.006666666666666667 --set 'study.resolutions=[3]' --set integrator.end_time=3 "
      "--set study.very_weak_sph=false --set study.small_velocity_factor=0 --set output.png=false "
      "--set method.viscosity_alpha=0 --out " +
          out.string(),
      "blowup");
  EXPECT_TRUE(run.exited);
  EXPECT_EQ(run.exitCode, 3) << run.log;
  EXPECT_NE(run.log.find("blew up at step"), std::string::npos) << run.log;
  EXPECT_NE(run.log.find("fastest particle"), std::string::npos) << run.log;
  EXPECT_FALSE(fs::exists(out / "summary.json"));
  EXPECT_FALSE(fs::exists(out / "cases.csv"));
}

// The very weak SPH plate below its smoothing rate (3000 1/s; the study's 1e4 keeps it bounded)
// grows: its energy ledger stops the run (exit 3) with the step, time, particle and likely cause.
TEST(PlateStudy, TheVeryWeakPlateStopsWhenItGrows) {
  const fs::path out = fs::temp_directory_path() / "mfwave-plate-vwsph-growth";
  fs::remove_all(out);
  const StudyOutcome run = runPlate(
      "--set 'study.resolutions=[5]' --set integrator.end_time=0.05 --set study.linearised_modes=false "
      "--set output.vtk=false --set output.png=false --set study.small_velocity_factor=0.01 "
      "--set study.very_weak_smoothing_rate=3000 --out " + out.string(),
      "vwsph-growth");
  EXPECT_TRUE(run.exited);
  EXPECT_EQ(run.exitCode, 3) << run.log;
  for (const char* part : {"energy growth at step", "fastest particle", "study.very_weak_smoothing_rate"})
    EXPECT_NE(run.log.find(part), std::string::npos) << part << " missing in: " << run.log;
}
