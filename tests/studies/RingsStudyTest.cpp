// Runs the rings driver as a user would, at a coarse spacing (dp = 2 mm: 5 particle circles across
// each ring wall, 1100 particles, ~5200 steps per case) with h = 1.3 dp: with the Monaghan-Gray
// artificial stress the rings bounce off each other whole; without it the tensile instability
// clumps the particles and tears the rings. (With the scene's h = 1.5 dp the nearest neighbours
// sit at the cubic spline's inflection point 2h/3, where the instability is marginal, and at this
// coarse spacing both cases stay whole; docs/studies/sph-solids.md.) The figures asserted are those
// the doc reports for this spacing, with margins for changes to the method that keep its physics.
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

struct Outcome {
  bool exited;
  int exitCode;
  std::string log;
};

Outcome runRings(const std::string& arguments, const std::string& name) {
  const fs::path log = fs::temp_directory_path() / ("mfwave-rings-" + name + ".log");
  const std::string command = std::string(RINGS_EXECUTABLE) + " --quiet --scene " + SCENES_FOLDER + "/rings.toml " +
                              arguments + " > " + log.string() + " 2>&1";
  const int status = std::system(command.c_str());
  std::ifstream in(log);
  std::stringstream text;
  text << in.rdbuf();
  return {WIFEXITED(status) != 0, WIFEXITED(status) ? WEXITSTATUS(status) : -1, text.str()};
}

std::map<std::string, double> section(const fs::path& summaryPath, const char* name) {
  const nlohmann::json summary = nlohmann::json::parse(std::ifstream(summaryPath));
  std::map<std::string, double> found;
  for (const auto& [key, value] : summary[name].items()) found[key] = value.get<double>();
  return found;
}

}  // namespace

TEST(RingsStudy, CoarseRingsReboundWholeOnlyWithTheArtificialStress) {
  const fs::path out = fs::temp_directory_path() / "mfwave-rings-coarse";
  fs::remove_all(out);
  const Outcome run = runRings(
      "--set geometry.spacing=0.002 --set method.smoothing_length_ratio=1.3 --set output.png=false "
      "--set output.every=2000 --out " +
          out.string(),
      "coarse");
  ASSERT_TRUE(run.exited && run.exitCode == 0) << run.log;
  EXPECT_EQ(mfwave::testing::summaryDisagreements(out), std::vector<std::string>{});  // every output listed
  for (const char* file : {"cases.csv", "summary.json", "scene.resolved.toml", "artificial_stress-energy.csv",
                           "artificial_stress-rings.csv", "artificial_stress-positions.csv", "artificial_stress.pvd",
                           "artificial_stress_000001.vtp", "no_artificial_stress-energy.csv",
                           "no_artificial_stress-positions.csv", "no_artificial_stress.pvd"})
    EXPECT_TRUE(fs::exists(out / file)) << file;

  const auto errors = section(out / "summary.json", "errors");
  const auto f = section(out / "summary.json", "figures");
  // No exact solution: the energy balance (kinetic + internal, with the viscous heating and the
  // work of the artificial stress in the internal energy) holds to 1e-5 of the initial energy in
  // both cases (measured 9.8e-6), so what separates them is physics, not time-integration error.
  EXPECT_LT(errors.at("artificial_stress_largest_balance_drift"), 1e-4);
  EXPECT_LT(errors.at("no_artificial_stress_largest_balance_drift"), 1e-4);

  // With the artificial stress: two intact rings (no link of the initial particle graph torn, no
  // stray particle), no clumping (smallest spacing 0.80 dp), and a rebound at 0.76 of the approach
  // speed, the rings apart at the end.
  EXPECT_EQ(errors.at("artificial_stress_extra_fragments"), 0);
  EXPECT_EQ(f.at("artificial_stress_fragments"), 2);
  EXPECT_EQ(f.at("artificial_stress_stray_particles"), 0);
  EXPECT_EQ(f.at("artificial_stress_torn_links"), 0);
  EXPECT_GT(f.at("artificial_stress_smallest_spacing_ratio"), 0.6);
  EXPECT_NEAR(f.at("artificial_stress_restitution_left"), 0.76, 0.08);
  EXPECT_NEAR(f.at("artificial_stress_restitution_right"), f.at("artificial_stress_restitution_left"), 1e-6);
  EXPECT_GT(f.at("artificial_stress_separation_time [s]"), f.at("artificial_stress_contact_time [s]"));
  EXPECT_GT(f.at("artificial_stress_contact_time [s]"), 0);

  // Without it: particles clump (smallest spacing 0.13 dp), links tear (24 at this spacing: a
  // crack through the wall), and most of the kinetic energy stays in the wreck (rebound 0.30).
  // The fragment count itself is not asserted: at this spacing the cracks leave the rings in 2
  // pieces (3 at dp = 1.6 mm, 6 at 1 mm, all with h = 1.3 dp).
  EXPECT_LT(f.at("no_artificial_stress_smallest_spacing_ratio"), 0.3);
  EXPECT_GT(f.at("no_artificial_stress_torn_links"), 10);
  EXPECT_LT(f.at("no_artificial_stress_restitution_left"), 0.5);
  EXPECT_LT(f.at("no_artificial_stress_restitution_left"), f.at("artificial_stress_restitution_left") - 0.3);
}

TEST(RingsStudy, BadInputNamesItsKey) {
  const fs::path out = fs::temp_directory_path() / "mfwave-rings-bad";
  fs::remove_all(out);
  Outcome run = runRings("--set shape[1].outer_radius=0.035 --out " + out.string(), "bad-radius");  // unequal rings
  EXPECT_TRUE(run.exited);
  EXPECT_EQ(run.exitCode, 2) << run.log;
  EXPECT_NE(run.log.find("shape[1].outer_radius"), std::string::npos) << run.log;
  run = runRings("--set 'study.cases=[\"artificial_stress\", \"sticky\"]' --out " + out.string(), "bad-case");
  EXPECT_EQ(run.exitCode, 2) << run.log;
  EXPECT_NE(run.log.find("study.cases"), std::string::npos) << run.log;
  run = runRings("--set shape[0].centre=[-0.07,0.0] --set shape[1].centre=[0.07,0.0] --out " + out.string(), "bad-window");  // the rings leave the window
  EXPECT_EQ(run.exitCode, 2) << run.log;
  EXPECT_NE(run.log.find("geometry.upper"), std::string::npos) << run.log;
  run = runRings("--set method.name=finite_difference --out " + out.string(), "bad-method");
  EXPECT_EQ(run.exitCode, 2) << run.log;
  EXPECT_NE(run.log.find("method"), std::string::npos) << run.log;
  // An end time of 1e300 is about 1e307 steps of the method's criteria: a typo, not a run (it used
  // to run on for ever).
  run = runRings("--set integrator.end_time=1e300 --out " + out.string(), "bad-end");
  EXPECT_EQ(run.exitCode, 2) << run.log;
  EXPECT_NE(run.log.find("integrator.end_time: 1e+300 s at the first step of"), std::string::npos) << run.log;
  EXPECT_FALSE(fs::exists(out / "summary.json"));
}

// A step twenty times the method's own criteria blows both cases up within a few steps: the ledger
// stops each case, every case's outputs are still written, and the run exits 3 naming the case,
// the step and the fastest particle.
TEST(RingsStudy, ACaseThatBlowsUpMakesTheRunFail) {
  const fs::path out = fs::temp_directory_path() / "mfwave-rings-blowup";
  fs::remove_all(out);
  const Outcome run = runRings("--set geometry.spacing=0.0025 --set output.vtk=false --set output.png=false "
                               "--set integrator.end_time=4e-4 --set integrator.cfl=20 --out " + out.string(),
                               "blowup");
  ASSERT_TRUE(run.exited);
  EXPECT_EQ(run.exitCode, 3) << run.log;
  EXPECT_NE(run.log.find("was stopped"), std::string::npos) << run.log;
  EXPECT_NE(run.log.find("blew up at step"), std::string::npos) << run.log;
  EXPECT_NE(run.log.find("fastest particle"), std::string::npos) << run.log;
  EXPECT_TRUE(fs::exists(out / "summary.json"));
  EXPECT_TRUE(fs::exists(out / "cases.csv"));
}
