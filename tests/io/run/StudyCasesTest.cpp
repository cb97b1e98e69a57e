// lib/io/run/StudyCases: runCases runs a plan in order and says when each case is done; a summary
// built from what ran takes every case's record whole, in run order.

#include "io/run/StudyCases.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

namespace mfwave {
namespace {

struct Result : StudyCase {
  int spacing = 0;
};

Result runOne(int spacing) {
  Result r;
  r.spacing = spacing;
  r.record.name = "n = " + std::to_string(spacing);
  r.record.particles = spacing * spacing;
  r.record.steps = 10 * spacing;
  r.record.loopSeconds = 0.5;
  r.record.errors = {{"relative_l2", 1.0 / spacing}};
  r.record.primaryError = "relative_l2";
  r.files = {"n" + std::to_string(spacing) + ".csv"};
  return r;
}

TEST(StudyCases, RunsThePlanInOrderAndSaysWhenEachIsDone) {
  std::ostringstream said;
  std::streambuf* old = std::cerr.rdbuf(said.rdbuf());
  const std::vector<Result> results = runCases(std::vector<int>{4, 8, 16}, runOne, true);
  std::cerr.rdbuf(old);
  ASSERT_EQ(results.size(), 3u);
  EXPECT_EQ(results[0].spacing, 4);
  EXPECT_EQ(results[2].record.name, "n = 16");
  EXPECT_EQ(said.str(), "  done n = 4 (16 particles, 40 steps)\n  done n = 8 (64 particles, 80 steps)\n"
                        "  done n = 16 (256 particles, 160 steps)\n");

  std::ostringstream quiet;
  old = std::cerr.rdbuf(quiet.rdbuf());
  runCases(std::vector<int>{4}, runOne, false);
  std::cerr.rdbuf(old);
  EXPECT_EQ(quiet.str(), "");
}

TEST(StudyCases, ASummaryTakesEveryRecordWholeInRunOrder) {
  const std::vector<Result> results = runCases(std::vector<int>{4, 8}, runOne, false);
  RunSummary summary("study", "scene", "method", "integrator");
  EXPECT_EQ(summary.program, "study");
  EXPECT_EQ(summary.scene, "scene");
  EXPECT_EQ(summary.method, "method");
  EXPECT_EQ(summary.integrator, "integrator");
  EXPECT_EQ(summary.files.entries().front(), "scene.resolved.toml");
  summary.addCases(results);
  summary.mergeNotesAndFiles(results);
  summary.totalsFromCases();
  ASSERT_EQ(summary.cases.size(), 2u);
  EXPECT_EQ(summary.cases[1].name, "n = 8");
  EXPECT_EQ(summary.cases[1].errors, results[1].record.errors);
  EXPECT_TRUE(std::isfinite(summary.cases[0].peakMemoryMiB));  // filled when the record had none
  EXPECT_EQ(summary.particles, 64);
  EXPECT_EQ(summary.steps, 120);
  EXPECT_EQ(summary.files.entries(), (std::vector<std::string>{"scene.resolved.toml", "n4.csv", "n8.csv"}));
}

TEST(StudyCases, AStudyLedByItsFirstCaseTakesItsHeadlineAndSumsTheCost) {
  std::vector<Result> results = runCases(std::vector<int>{16, 4}, runOne, false);
  results[0].record.timeStep = 0.01;
  results[0].record.simulatedTime = 2;
  for (Result& r : results) r.record.setupSeconds = 0.25;
  RunSummary summary("study", "scene", "method", "integrator");
  summary.addCases(results);
  summary.totalsFromFirstCase();
  EXPECT_EQ(summary.particles, 256);  // the first case's, not the largest by chance
  EXPECT_EQ(summary.timeStep, 0.01);
  EXPECT_EQ(summary.simulatedTime, 2);
  EXPECT_EQ(summary.steps, 200);
  EXPECT_DOUBLE_EQ(summary.wallSeconds, 2 * (0.25 + 0.5));  // set-up and loop of every case
}

}  // namespace
}  // namespace mfwave
