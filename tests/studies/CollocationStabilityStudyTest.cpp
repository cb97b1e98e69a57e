// The stability and dispersion tools run as a user would: from their scenes, writing the CSVs.

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace {

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST(CollocationStabilityStudy, StabilityToolWritesTheTable) {
  const std::string out = std::filesystem::temp_directory_path() / "mfwave-stability-study";
  const std::string command = std::string(STABILITY_EXECUTABLE) + " --quiet --scene " SCENES_FOLDER
                              "/collocation-stability.toml --set study.rk_reference=\"" REFERENCE_FOLDER
                              "/luo2011-table1-rkcm-critical-dt.csv\" --set study.rb_reference=\"" REFERENCE_FOLDER
                              "/luo2011-table2-rbcm-critical-dt.csv\" --out " + out + " > " + out + ".log";
  std::filesystem::create_directories(out);
  ASSERT_EQ(std::system(command.c_str()), 0) << slurp(out + ".log");
  const std::string table = slurp(out + "/stability.csv");
  EXPECT_NE(table.find("read as c * dt"), std::string::npos);
  EXPECT_NE(table.find("rbcm,3,"), std::string::npos);
  EXPECT_NE(table.find("unconditionally unstable (complex pair"), std::string::npos);  // RKCM a/h = 6.3
  EXPECT_TRUE(std::filesystem::exists(out + "/summary.json"));
}

TEST(CollocationStabilityStudy, DispersionToolWritesTheCurves) {
  const std::string out = std::filesystem::temp_directory_path() / "mfwave-dispersion-study";
  const std::string command = std::string(DISPERSION_EXECUTABLE) + " --quiet --scene " SCENES_FOLDER
                              "/collocation-dispersion.toml --out " + out + " > " + out + ".log";
  std::filesystem::create_directories(out);
  ASSERT_EQ(std::system(command.c_str()), 0) << slurp(out + ".log");
  EXPECT_NE(slurp(out + "/dispersion.csv").find("method,order,ratio,kh,phase_speed,group_speed"), std::string::npos);
}
