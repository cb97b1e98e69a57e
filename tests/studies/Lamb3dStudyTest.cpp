// Runs the lamb3d driver as a user would, on the paper's resolution (spacing 0.5, 3375
// particles): its outputs exist, and the published scheme's errors against the exact half-space
// response are what docs/studies/lamb3d.md reports, so a change to the method shows up here.
#include "support/StudyRun.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

struct LambOutcome {
  bool exited;
  int exitCode;
  std::string log;
};

LambOutcome runLamb3d(const std::string& arguments, const std::string& name) {
  const fs::path log = fs::temp_directory_path() / ("mfwave-lamb3d-" + name + ".log");
  const std::string command = std::string(LAMB3D_EXECUTABLE) + " --quiet --scene " + SCENES_FOLDER +
                              "/lamb3d.toml " + arguments + " > " + log.string() + " 2>&1";
  const int status = std::system(command.c_str());
  std::ifstream in(log);
  std::stringstream text;
  text << in.rdbuf();
  return {WIFEXITED(status) != 0, WIFEXITED(status) ? WEXITSTATUS(status) : -1, text.str()};
}

std::map<std::string, double> errors(const fs::path& summaryPath) {
  const nlohmann::json summary = nlohmann::json::parse(std::ifstream(summaryPath));
  std::map<std::string, double> found;
  for (const auto& [key, value] : summary["errors"].items()) found[key] = value.get<double>();
  return found;
}

}  // namespace

TEST(Lamb3dStudy, PaperResolutionReproducesTheMeasuredErrors) {
  const fs::path out = fs::temp_directory_path() / "mfwave-lamb3d-paper";
  fs::remove_all(out);
  const LambOutcome run = runLamb3d("--set 'study.spacings=[0.5]' --set output.every=11 --out " + out.string(), "paper");
  ASSERT_TRUE(run.exited && run.exitCode == 0) << run.log;
  EXPECT_EQ(mfwave::testing::summaryDisagreements(out), std::vector<std::string>{});  // every output listed
  for (const char* file : {"cases.csv", "galerkin_0.5-probes.csv", "published_0.5-probes.csv",
                           "strong_filter-probes.csv", "free_block-probes.csv", "exact.csv", "galerkin_0.5.pvd",
                           "galerkin_0.5_000004.vtp", "galerkin_0.5-energy.csv", "summary.json", "scene.resolved.toml"})
    EXPECT_TRUE(fs::exists(out / file)) << file;

  const auto e = errors(out / "summary.json");
  // The published scheme at the paper's resolution (docs/studies/lamb3d.md): the deconvolved
  // centre velocity is within about 27 % (L2) of the exact one, its peak within 4 %; the receiver
  // 2 units away is off by about 55 % and its Rayleigh peak is 63 % too small.
  EXPECT_NEAR(e.at("published_0.5_centre_relative_l2"), 0.266, 0.01);
  EXPECT_NEAR(e.at("published_0.5_centre_peak_error"), 0.033, 0.01);
  EXPECT_NEAR(e.at("published_0.5_receiver_relative_l2"), 0.555, 0.02);
  EXPECT_NEAR(e.at("published_0.5_receiver_peak_error"), -0.63, 0.03);
  // Deconvolution (eq. 35) is what makes the centre usable: without it the error is 45 %.
  EXPECT_NEAR(e.at("published_0.5_centre_relative_l2_raw"), 0.453, 0.01);
  // The paper's Fig. 4: alpha = 0.5 per step smooths the raw field further (the raw peak halves).
  EXPECT_GT(e.at("strong_filter_centre_relative_l2_raw"), e.at("published_0.5_centre_relative_l2_raw"));
  // The scene's (Galerkin) variant at the paper's resolution (docs/studies/lamb3d.md): coarse, but it
  // converges (the spacing cases); better than the consistent variant's 0.293 / 0.840 here.
  EXPECT_NEAR(e.at("galerkin_0.5_centre_relative_l2"), 0.2245, 0.005);
  EXPECT_NEAR(e.at("galerkin_0.5_receiver_relative_l2"), 0.8386, 0.01);
  // 1 below the centre, against the f-k reference (the receiver the exact surface solution cannot score).
  EXPECT_NEAR(e.at("galerkin_0.5_buried_relative_l2"), 0.606, 0.01);
  EXPECT_NEAR(e.at("published_0.5_buried_relative_l2"), 0.363, 0.01);
  // Within 0 <= t <= 6 the transmitting faces and a block twice as wide with free faces give
  // receiver errors within 0.01 of each other (0.8386 and 0.8406): reflections from faces 3.5 units
  // away barely reach the surface probes.
  EXPECT_NEAR(e.at("free_block_receiver_relative_l2"), e.at("galerkin_0.5_receiver_relative_l2"), 0.015);
  EXPECT_NEAR(e.at("free_block_centre_relative_l2"), e.at("galerkin_0.5_centre_relative_l2"), 0.005);
}

// The spectral-element reference in 3-D (method.name = spectral_element, GLL order 4, cubic elements
// of side 1 at spacing 0.25: 29^3 nodes, sum-factorised stiffness): it runs the scene, its
// measured errors against the exact response are what lib/studies/lamb3d/LambSpectralElementCase
// gave when it was written.
TEST(Lamb3dStudy, SpectralElementsRunTheScene) {
  const fs::path out = fs::temp_directory_path() / "mfwave-lamb3d-sem";
  fs::remove_all(out);
  const LambOutcome run = runLamb3d("--set method.name=spectral_element --set geometry.spacing=0.25 "
                                    "--set 'study.spacings=[0.25]' --set output.vtk=false --out " + out.string(),
                                    "sem");
  ASSERT_TRUE(run.exited);
  ASSERT_EQ(run.exitCode, 0) << run.log;
  for (const char* file : {"cases.csv", "exact.csv", "sem_n4_0.25-probes.csv"})
    EXPECT_TRUE(fs::exists(out / file)) << file;
  EXPECT_TRUE(mfwave::testing::summaryDisagreements(out).empty());
  const std::map<std::string, double> e = errors(out / "summary.json");
  // Measured (0.148 / 0.171 / 0.187; the very weak SPH Galerkin variant gives 0.10 / 0.21 / 0.20 here).
  EXPECT_NEAR(e.at("sem_n4_0.25_centre_relative_l2"), 0.148, 0.004);
  EXPECT_NEAR(e.at("sem_n4_0.25_receiver_relative_l2"), 0.171, 0.004);
  EXPECT_NEAR(e.at("sem_n4_0.25_buried_relative_l2"), 0.187, 0.004);
  std::ifstream summaryFile(out / "summary.json");
  std::stringstream summary;
  summary << summaryFile.rdbuf();
  EXPECT_NE(summary.str().find("runs no free_block case"), std::string::npos);
  // the 7-wide block in elements of side 1: the loaded square |x|, |y| < 0.5 is the centre element's face
  EXPECT_EQ(summary.str().find("falls inside an element"), std::string::npos);
}

// The updated-Lagrangian SPH in 3-D (method.name = updated_lagrangian_sph) at the scene's spacing 0.5:
// it runs the scene's box (15^3 particles, every face free; the free block is ignored with a note),
// and its errors are what lib/studies/lamb3d/LambSolidCase.hpp measured.
TEST(Lamb3dStudy, TheUpdatedLagrangianSphRunsTheScene) {
  const fs::path out = fs::temp_directory_path() / "mfwave-lamb3d-ulsph";
  fs::remove_all(out);
  const LambOutcome run = runLamb3d("--set method.name=updated_lagrangian_sph --set 'study.spacings=[0.5]' "
                                    "--set output.vtk=false --out " + out.string(),
                                    "ulsph");
  ASSERT_TRUE(run.exited);
  ASSERT_EQ(run.exitCode, 0) << run.log;
  for (const char* file : {"cases.csv", "exact.csv", "ulsph_0.5-probes.csv"})
    EXPECT_TRUE(fs::exists(out / file)) << file;
  EXPECT_TRUE(mfwave::testing::summaryDisagreements(out).empty());
  const std::map<std::string, double> e = errors(out / "summary.json");
  EXPECT_NEAR(e.at("ulsph_0.5_centre_relative_l2"), 1.323, 0.02);
  EXPECT_NEAR(e.at("ulsph_0.5_receiver_relative_l2"), 0.882, 0.02);
  EXPECT_NEAR(e.at("ulsph_0.5_buried_relative_l2"), 1.128, 0.02);
  std::ifstream summaryFile(out / "summary.json");
  std::stringstream summary;
  summary << summaryFile.rdbuf();
  EXPECT_NE(summary.str().find("updated_lagrangian_sph runs no free_block case"), std::string::npos);
  EXPECT_NE(summary.str().find("reaches a probe at t = 2.6"), std::string::npos);
  EXPECT_NE(summary.str().find("\"leapfrog\""), std::string::npos);
  std::ifstream cases(out / "cases.csv");
  std::string header, first;
  std::getline(cases, header);
  std::getline(cases, first);
  EXPECT_EQ(first.rfind("ulsph_0.5,ul-sph alpha=1 beta=0 kgc,,0.5,0.65,3375,", 0), 0u) << first;
}

// RK collocation in 3-D (method.name = reproducing_kernel) at the paper's spacing with the default
// support, a / h = 2.2 in 3-D (the widest whose interior does not grow): it runs the scene, its
// measured errors are what docs/studies/lamb3d.md reports, and the scene's free block is read and
// ignored with a note.
TEST(Lamb3dStudy, RkCollocationRunsTheSceneAtTheStable3dSupport) {
  const fs::path out = fs::temp_directory_path() / "mfwave-lamb3d-rk";
  fs::remove_all(out);
  const LambOutcome run = runLamb3d("--set method.name=reproducing_kernel --set 'study.spacings=[0.5]' "
                                    "--set output.vtk=false --out " + out.string(),
                                    "rk");
  ASSERT_TRUE(run.exited);
  ASSERT_EQ(run.exitCode, 0) << run.log;
  for (const char* file : {"cases.csv", "exact.csv", "rk_m2_a2.2_0.5-probes.csv"})
    EXPECT_TRUE(fs::exists(out / file)) << file;
  EXPECT_TRUE(mfwave::testing::summaryDisagreements(out).empty());
  const std::map<std::string, double> e = errors(out / "summary.json");
  EXPECT_NEAR(e.at("rk_m2_a2.2_0.5_centre_relative_l2"), 0.281, 0.01);
  EXPECT_NEAR(e.at("rk_m2_a2.2_0.5_receiver_relative_l2"), 0.505, 0.02);
  EXPECT_NEAR(e.at("rk_m2_a2.2_0.5_buried_relative_l2"), 0.368, 0.01);
  std::ifstream summaryFile(out / "summary.json");
  std::stringstream summary;
  summary << summaryFile.rdbuf();
  EXPECT_NE(summary.str().find("reproducing_kernel runs no free_block case"), std::string::npos);
  EXPECT_NE(summary.str().find("INSIDE the error window 6"), std::string::npos);
}

TEST(Lamb3dStudy, WrongMethodAndBadSpacingNameTheirKeys) {
  const fs::path out = fs::temp_directory_path() / "mfwave-lamb3d-bad";
  fs::remove_all(out);
  LambOutcome run = runLamb3d("--set method.name=finite_difference --out " + out.string(), "bad-method");
  EXPECT_TRUE(run.exited);
  EXPECT_EQ(run.exitCode, 2) << run.log;
  EXPECT_NE(run.log.find("method"), std::string::npos) << run.log;
  run = runLamb3d("--set 'study.spacings=[0.3]' --out " + out.string(), "bad-spacing");
  EXPECT_EQ(run.exitCode, 2) << run.log;
  EXPECT_NE(run.log.find("study.spacings[0]"), std::string::npos) << run.log;
  EXPECT_FALSE(fs::exists(out / "summary.json"));
}

// Issue 15: a run whose energy grows after the load has ended is stopped (exit 3) with the step,
// the time, the particle and the cause, and what it recorded so far stays readable. The published
// operator without its filter grows from t of about 50 at the paper's spacing
// (docs/theory/very-weak-sph.md).
TEST(Lamb3dStudy, AnUnfilteredPublishedRunThatGrowsIsStoppedWithExitThree) {
  const fs::path out = fs::temp_directory_path() / "mfwave-lamb3d-grows";
  fs::remove_all(out);
  const std::string common = "--set 'study.spacings=[0.5]' --set method.variant=published --set method.smoothing_rate=0 "
                             "--set output.vtk=false --set output.png=false ";
  LambOutcome run = runLamb3d(common + "--set integrator.end_time=300 --out " + out.string(), "grows");
  ASSERT_TRUE(run.exited);
  EXPECT_EQ(run.exitCode, 3) << run.log;
  for (const char* part : {"energy growth at step ", ", t = ", "particle", "published operator has growing modes"})
    EXPECT_NE(run.log.find(part), std::string::npos) << part << " missing in: " << run.log;
  EXPECT_FALSE(fs::exists(out / "summary.json"));
  // The energy ledger up to the stop: rows from t = 0 to the stop, well before t = 300.
  std::ifstream ledger(out / "published_0.5-energy.csv");
  ASSERT_TRUE(ledger.good());
  std::string line, last;
  std::getline(ledger, line);
  EXPECT_EQ(line.rfind("t [s],kinetic [J],strain [J],load_work [J],dashpot_loss [J],filter_loss [J],balance [J]", 0), 0u);
  while (std::getline(ledger, line)) last = line;
  const double stoppedAt = std::stod(last.substr(0, last.find(',')));
  EXPECT_GT(stoppedAt, 40);
  EXPECT_LT(stoppedAt, 200);

  // On purpose: stability.allow_growth runs on and says so in the summary.
  fs::remove_all(out);
  // (to t = 120, past the stop above; the free-faces case on the scene's own box, not the wide one)
  run = runLamb3d(common + "--set integrator.end_time=120 --set stability.allow_growth=true "
                           "--set study.strong_smoothing_rate=0 --set 'study.free_block_lower=[-3.5,-3.5,-7.0]' "
                           "--set 'study.free_block_upper=[3.5,3.5,0.0]' --out " + out.string(),
                  "grows-allowed");
  EXPECT_EQ(run.exitCode, 0) << run.log;
  const nlohmann::json summary = nlohmann::json::parse(std::ifstream(out / "summary.json"));
  EXPECT_NE(summary.dump().find("allow_growth let the run go on through"), std::string::npos);
}

// The consistent variant with the filter it used to ship with (rate 0.5 at dx = 0.5, scaled as 1 / dx)
// at dx = 0.25 over a long run grows from about t = 50 (docs/theory/very-weak-sph.md); the guard
// stops it instead of reporting success.
TEST(Lamb3dStudy, TheFilteredConsistentVariantAtHalfSpacingIsStoppedInALongRun) {
  const fs::path out = fs::temp_directory_path() / "mfwave-lamb3d-consistent-long";
  fs::remove_all(out);
  const LambOutcome run = runLamb3d("--set 'study.spacings=[0.25]' --set geometry.spacing=0.25 --set study.compare_published=false "
                                "--set method.variant=consistent --set method.smoothing_rate=0.5 "
                                "--set output.vtk=false --set output.png=false --set integrator.end_time=300 --out " +
                                    out.string(),
                                "consistent-long");
  ASSERT_TRUE(run.exited);
  EXPECT_EQ(run.exitCode, 3) << run.log;
  EXPECT_NE(run.log.find("consistent variant's corrected boundary rows are not symmetric"), std::string::npos) << run.log;
}

// Issue 15's command: the shipped scene (the Galerkin variant: symmetric positive semi-definite
// operator, dissipative dashpots, no filter) run 50 x the study's window at dx = 0.25, with a
// free-faces case on the same box. It exits 0, its energy after t = 300 is below 1e-4 of its
// largest (1.9e-5 measured; what remains are grid-scale waves at 0.5-0.7 omega_max whose group
// velocity is near zero, so no dashpot reaches them; docs/theory/very-weak-sph.md), and within the
// window it is as accurate as the consistent variant (centre 0.104, receiver 0.211 against 0.109
// and 0.255).
TEST(Lamb3dStudy, TheGalerkinVariantRunsFiftyWindowsWithoutAFilterAndItsEnergyOnlyFalls) {
  const fs::path out = fs::temp_directory_path() / "mfwave-lamb3d-galerkin-long";
  fs::remove_all(out);
  const LambOutcome run = runLamb3d("--set 'study.spacings=[0.25]' --set geometry.spacing=0.25 --set study.compare_published=false "
                                "--set 'study.free_block_lower=[-3.5,-3.5,-7.0]' --set 'study.free_block_upper=[3.5,3.5,0.0]' "
                                "--set output.vtk=false --set output.png=false --set integrator.end_time=300 --out " +
                                    out.string(),
                                "galerkin-long");
  ASSERT_TRUE(run.exited);
  ASSERT_EQ(run.exitCode, 0) << run.log;
  const nlohmann::json summary = nlohmann::json::parse(std::ifstream(out / "summary.json"));
  EXPECT_LT(summary["figures"]["galerkin_0.25_energy_final_fraction"].get<double>(), 1e-4);
  EXPECT_LT(summary["figures"]["galerkin_0.25_energy_balance_drift"].get<double>(), 0.01);
  const auto e = errors(out / "summary.json");
  EXPECT_NEAR(e.at("galerkin_0.25_centre_relative_l2"), 0.104, 0.005);
  EXPECT_NEAR(e.at("galerkin_0.25_receiver_relative_l2"), 0.211, 0.01);
  EXPECT_NEAR(e.at("galerkin_0.25_buried_relative_l2"), 0.198, 0.01);
}
