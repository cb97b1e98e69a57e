#include "core/Error.hpp"
#include "io/run/ProgressReporter.hpp"
#include "io/run/RunDriver.hpp"
#include "io/run/RunSummary.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <type_traits>
#include <vector>

using namespace mfwave;

TEST(ProgressReporter, ShowsStepTimeRateAndTimeLeft) {
  std::ostringstream out;
  ProgressReporter progress(2.0, 1000, out, 0.0);
  const Vector u = Vector::Zero(3);
  progress.begin({0, 0.0, u, u});
  // Half the simulated time after 10 s of wall time for 500 steps: 5e4 particle-steps/s, 10 s left.
  const std::string line = progress.line({500, 1.0, u, u}, 10.0);
  EXPECT_NE(line.find("step 500"), std::string::npos) << line;
  EXPECT_NE(line.find("(50 %)"), std::string::npos) << line;
  EXPECT_NE(line.find("5.00e+04 particle-steps/s"), std::string::npos) << line;
  EXPECT_NE(line.find("left 10 s"), std::string::npos) << line;
  progress.observe({1, 0.1, u, u});
  EXPECT_NE(out.str().find("step 1"), std::string::npos);
}

// Restored from a checkpoint (restoreState in place of begin()): the share done still counts from
// the run's start, the rate and the time left from the state the checkpoint was taken at.
TEST(ProgressReporter, RestoredCountsTheShareFromTheStartAndTheRateFromTheCheckpoint) {
  std::ostringstream out;
  ProgressReporter before(2.0, 1000, out, 0.0);
  const Vector u = Vector::Zero(3);
  before.begin({0, 0.0, u, u});
  before.observe({400, 0.8, u, u});
  StateArchive archive;
  before.saveState(archive);
  ProgressReporter after(2.0, 1000, out, 0.0);
  after.restoreState(archive);
  // 100 steps and 0.2 s simulated in 2 s of wall time since the restart: 5e4 particle-steps/s,
  // 1.0 s simulated left at 0.1 s per wall second: 10 s.
  const std::string line = after.line({500, 1.0, u, u}, 2.0);
  EXPECT_NE(line.find("(50 %)"), std::string::npos) << line;
  EXPECT_NE(line.find("5.00e+04 particle-steps/s"), std::string::npos) << line;
  EXPECT_NE(line.find("left 10 s"), std::string::npos) << line;
}

TEST(ProgressReporter, StaysQuietWhenNotOnATerminal) {
  // ctest pipes standard error, so the terminal check fails and nothing is printed.
  if (::isatty(STDERR_FILENO)) GTEST_SKIP() << "standard error is a terminal here";
  ProgressReporter progress(1.0, 10, true);
  EXPECT_FALSE(progress.enabled());
}

TEST(RunSummary, WritesEveryFigureAsJson) {
  RunSummary s;
  s.program = "wavefield";
  s.scene = "block-ricker";
  s.particles = 9261;
  s.meanNeighbours = 7;
  s.steps = 100;
  s.wallSeconds = 2;
  s.errors = {{"relative_l2", 0.125}};
  s.notes.add("no PNG: no display");
  s.finish();
  EXPECT_GT(s.peakMemoryMiB, 1.0);
  EXPECT_DOUBLE_EQ(s.particleStepsPerSecond(), 9261 * 100 / 2.0);
  const auto path = std::filesystem::temp_directory_path() / "mfwave-summary.json";
  s.writeJson(path.string());
  const nlohmann::json j = nlohmann::json::parse(std::ifstream(path));
  EXPECT_EQ(j["particles"], 9261);
  EXPECT_DOUBLE_EQ(j["errors"]["relative_l2"].get<double>(), 0.125);
  EXPECT_DOUBLE_EQ(j["particle_steps_per_second"].get<double>(), 463050.0);
  EXPECT_EQ(j["notes"][0], "no PNG: no display");
  // Which build made it: the project's version and the revision CMake read at configure time.
  EXPECT_EQ(j["mfwave_version"], MFWAVE_EXPECTED_VERSION);
  EXPECT_EQ(j["git_revision"], MFWAVE_EXPECTED_REVISION);
  std::ostringstream text;
  s.print(text);
  EXPECT_NE(text.str().find("particles 9261"), std::string::npos) << text.str();
}

TEST(GrowingList, KeepsOrderAndListsEachEntryOnce) {
  GrowingList list;
  list.add("cases.csv");
  list.addAll({"a-tip.csv", "cases.csv", "b-tip.csv"});
  list.add("a-tip.csv");
  EXPECT_EQ(list.entries(), (std::vector<std::string>{"cases.csv", "a-tip.csv", "b-tip.csv"}));
  EXPECT_TRUE(list.contains("b-tip.csv"));
  EXPECT_FALSE(list.contains("summary.json"));
  static_assert(!std::is_copy_assignable_v<GrowingList>, "reassigning a list would lose its entries");
}

// The files of a summary: the resolved scene first, then what the driver added in order, then
// summary.json, each once, however often a driver listed them.
TEST(RunSummary, ListsTheResolvedSceneFirstAndItselfLast) {
  RunSummary s;
  s.files.add("cases.csv");
  s.files.add("modes.csv");
  s.files.add("cases.csv");
  s.files.add("scene.resolved.toml");
  s.notes.add("from case a");
  s.notes.addAll({"from case a", "from case b"});
  const auto folder = std::filesystem::temp_directory_path() / "mfwave-summary-files";
  std::filesystem::create_directories(folder);
  std::ostringstream text;
  s.conclude(folder.string(), &text);
  const nlohmann::json j = nlohmann::json::parse(std::ifstream(folder / "summary.json"));
  EXPECT_EQ(j["files"].get<std::vector<std::string>>(),
            (std::vector<std::string>{"scene.resolved.toml", "cases.csv", "modes.csv", "summary.json"}));
  EXPECT_EQ(j["notes"].get<std::vector<std::string>>(), (std::vector<std::string>{"from case a", "from case b"}));
  EXPECT_GT(j["peak_memory_mib"].get<double>(), 1.0);  // conclude() reads the peak memory
  EXPECT_NE(text.str().find("note: from case b"), std::string::npos) << text.str();
  std::filesystem::remove_all(folder);
}

TEST(RunSummary, MergeNotesAndFilesInCaseOrder) {
  struct Case {
    std::vector<std::string> notes, files;
  };
  RunSummary s;
  s.mergeNotesAndFiles(std::vector<Case>{{{"stopped early"}, {"a-tip.csv", "a.pvd"}}, {{"stopped early", "b: no period"}, {"b-tip.csv"}}});
  EXPECT_EQ(s.notes.entries(), (std::vector<std::string>{"stopped early", "b: no period"}));
  EXPECT_EQ(s.files.entries(), (std::vector<std::string>{"scene.resolved.toml", "a-tip.csv", "a.pvd", "b-tip.csv"}));
}

TEST(RunSummary, RateIsZeroWithoutTime) {
  EXPECT_DOUBLE_EQ(particleStepsPerSecond(1000, 10, 0), 0.0);
  EXPECT_DOUBLE_EQ(particleStepsPerSecond(1000, 10, 0.5), 20000.0);
  Stopwatch clock;
  EXPECT_GE(clock.seconds(), 0.0);
}

TEST(RunDriver, MapsErrorsToExitCodes) {
  testing::internal::CaptureStderr();
  EXPECT_EQ(runDriver("p", [] { return 0; }), 0);
  EXPECT_EQ(runDriver("p", []() -> int { throw InputError("geometry.spacing", "must be positive"); }), 2);
  EXPECT_EQ(runDriver("p", []() -> int { throw InstabilityError("blew up", 5, 0.5, 7); }), 3);
  EXPECT_EQ(runDriver("p", []() -> int { throw Error("disk full"); }), 1);
  const std::string err = testing::internal::GetCapturedStderr();
  EXPECT_NE(err.find("p: error: geometry.spacing: must be positive"), std::string::npos) << err;
  EXPECT_NE(err.find("p: run stopped: blew up"), std::string::npos) << err;
}
