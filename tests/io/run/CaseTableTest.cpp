#include "io/run/CaseTable.hpp"
#include "core/Error.hpp"
#include "io/run/RunSummary.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

using namespace mfwave;

namespace {

struct Case {
  std::string integrator;
  long particles;
  double dx, error, order;
  bool hasOrder;
};

std::string readFile(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

CaseTable<Case> table() {
  CaseTable<Case> t;
  t.column("integrator", [](const Case& c) { return c.integrator; }, TerminalColumn("integrator", 12).left())
      .column("particles", [](const Case& c) { return c.particles; }, TerminalColumn("N", 9))
      .column("dx [m]", [](const Case& c) { return c.dx; })
      .column("error", [](const Case& c) { return c.error; }, TerminalColumn("L2", 11).scientific().precision(2))
      .column("order", [](const Case& c) { return cellIf(c.hasOrder, c.order); },
              TerminalColumn("order", 7).precision(3))
      .terminalOnly(TerminalColumn("err", 6).fixed().precision(1).titledIn(7).followedBy("%"),
                    [](const Case& c) { return 100 * c.error; });
  return t;
}

const std::vector<Case> kCases = {{"leapfrog", 1234567, 0.1, 0.012345678901, 0, false},
                                  {"leapfrog", 9876543, 0.05, 0.003086419753, 2.000000000001, true},
                                  {"newmark", 17, 1.0 / 3.0, std::nan(""), 0, false}};

}  // namespace

// The file a hand-written writer produced (header, then values streamed at one precision), byte for
// byte: whole numbers stay whole, empty cells stay empty, NaN is "nan", terminal-only columns are
// not in the file.
TEST(CaseTable, WritesTheCsvAHandWrittenWriterWrote) {
  const auto path = std::filesystem::temp_directory_path() / "mfwave-case-table.csv";
  table().writeCsv(path.string(), kCases, 8);
  std::ostringstream expected;
  expected << "integrator,particles,dx [m],error,order\n" << std::setprecision(8);
  for (const Case& c : kCases) {
    expected << c.integrator << ',' << c.particles << ',' << c.dx << ',' << c.error << ',';
    if (c.hasOrder) expected << c.order;
    expected << '\n';
  }
  EXPECT_EQ(readFile(path), expected.str());
  EXPECT_NE(readFile(path).find(",1234567,"), std::string::npos);
  EXPECT_NE(readFile(path).find(",nan,\n"), std::string::npos);
  EXPECT_EQ(readFile(path).find("1.2345679e+06"), std::string::npos);
}

TEST(CaseTable, PrintsTheTerminalColumnsInTheirOwnFormats) {
  std::ostringstream out;
  out << std::setprecision(2);  // the table must neither depend on nor change the stream's format
  table().print(out, kCases);
  std::istringstream lines(out.str());
  std::string title, first, second;
  std::getline(lines, title);
  std::getline(lines, first);
  std::getline(lines, second);
  EXPECT_EQ(title, "integrator          N         L2  order    err");
  EXPECT_EQ(first, "leapfrog      1234567   1.23e-02          1.2%");
  EXPECT_EQ(second, "leapfrog      9876543   3.09e-03      2   0.3%");
  EXPECT_EQ(out.precision(), 2);
  EXPECT_FALSE(out.flags() & std::ios::scientific);
}

// The canonical case record: every field in summary.json's "cases", unknown values as null, the
// loop's particle-steps/s, the primary error's value next to its name.
TEST(RunSummary, WritesEveryCaseInTheCanonicalLayout) {
  RunSummary s;
  CaseRecord a;
  a.name = "64 cells";
  a.particles = 65;
  a.steps = 200;
  a.timeStep = 0.01;
  a.stableTimeStep = 0.0125;
  a.simulatedTime = 2;
  a.setupSeconds = 0.5;
  a.loopSeconds = 0.25;
  a.errors = {{"relative_l2_u", 0.03}, {"relative_l2_v", 0.04}};
  a.primaryError = "relative_l2_u";
  s.addCase(a);
  CaseRecord b;  // nothing measured but its name
  b.name = "skipped";
  s.addCase(b);
  const auto path = std::filesystem::temp_directory_path() / "mfwave-summary-cases.json";
  s.writeJson(path.string());
  const nlohmann::json j = nlohmann::json::parse(std::ifstream(path));
  ASSERT_EQ(j["cases"].size(), 2u);
  const auto& c = j["cases"][0];
  EXPECT_EQ(c["case"], "64 cells");
  EXPECT_EQ(c["particles"], 65);
  EXPECT_EQ(c["steps"], 200);
  EXPECT_DOUBLE_EQ(c["dt"].get<double>(), 0.01);
  EXPECT_DOUBLE_EQ(c["stable_dt"].get<double>(), 0.0125);
  EXPECT_DOUBLE_EQ(c["loop_seconds"].get<double>(), 0.25);
  EXPECT_DOUBLE_EQ(c["particle_steps_per_second"].get<double>(), 65 * 200 / 0.25);
  EXPECT_GT(c["peak_memory_mib"].get<double>(), 1.0);
  EXPECT_EQ(c["primary_error"], "relative_l2_u");
  EXPECT_DOUBLE_EQ(c["primary_error_value"].get<double>(), 0.03);
  EXPECT_DOUBLE_EQ(c["errors"]["relative_l2_v"].get<double>(), 0.04);
  const auto& d = j["cases"][1];
  EXPECT_TRUE(d["dt"].is_null());
  EXPECT_TRUE(d["loop_seconds"].is_null());
  EXPECT_TRUE(d["particle_steps_per_second"].is_null());
  EXPECT_TRUE(d["primary_error"].is_null());
}

TEST(RunSummary, WritesNoCasesWhenThereAreNone) {
  RunSummary s;
  const auto path = std::filesystem::temp_directory_path() / "mfwave-summary-no-cases.json";
  s.writeJson(path.string());
  EXPECT_FALSE(nlohmann::json::parse(std::ifstream(path)).contains("cases"));
}

TEST(RunSummary, RefusesAPrimaryErrorTheCaseDoesNotHave) {
  RunSummary s;
  CaseRecord a;
  a.name = "x";
  a.errors = {{"relative_l2_u", 0.1}};
  a.primaryError = "relative_l2_v";
  EXPECT_THROW(s.addCase(a), Error);
}
