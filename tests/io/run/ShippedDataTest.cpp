#include "core/Error.hpp"
#include "io/run/DriverCommandLine.hpp"
#include "io/run/ShippedData.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using namespace mfwave;
namespace fs = std::filesystem;

namespace {

// An installed tree in a temporary folder: <root>/bin/prog and <root>/share/mfwave/data/scenes/<name>.
fs::path installedTree(const std::string& name, const std::string& sceneName) {
  const fs::path root = fs::temp_directory_path() / ("mfwave-shipped-" + name);
  fs::remove_all(root);
  fs::create_directories(root / "bin");
  fs::create_directories(root / "share/mfwave/data/scenes");
  std::ofstream(root / "bin/prog") << "";
  std::ofstream(root / "share/mfwave/data/scenes" / sceneName) << "[scene]\nname = 'x'\n";
  return root;
}

// Unsets MFWAVE_DATA_DIR for the test and puts back what was there.
struct DataDirVariable {
  DataDirVariable() {
    if (const char* value = std::getenv("MFWAVE_DATA_DIR")) saved = value;
    unsetenv("MFWAVE_DATA_DIR");
  }
  ~DataDirVariable() {
    if (!saved.empty()) setenv("MFWAVE_DATA_DIR", saved.c_str(), 1);
    else unsetenv("MFWAVE_DATA_DIR");
  }
  std::string saved;
};

}  // namespace

TEST(ShippedData, FindsTheSceneBesideAnInstalledProgram) {
  DataDirVariable variable;
  const fs::path root = installedTree("installed", "x.toml");
  const auto found = findShippedFile("data/scenes/x.toml", (root / "bin/prog").string());
  ASSERT_TRUE(found.has_value());
  EXPECT_TRUE(fs::equivalent(*found, root / "share/mfwave/data/scenes/x.toml"));
  EXPECT_FALSE(findShippedFile("data/scenes/absent.toml", (root / "bin/prog").string()).has_value());
  // Outside the build folder the source tree is not a place: only the installed one.
  const std::vector<ShippedDataPlace> places = shippedDataPlaces((root / "bin/prog").string());
  ASSERT_EQ(places.size(), 1u);
  EXPECT_EQ(places[0].folder, (root / "share/mfwave").string());
}

TEST(ShippedData, TheVariableComesFirstAndTheSourceTreeLast) {
  DataDirVariable variable;
  const fs::path root = installedTree("variable", "x.toml");
  setenv("MFWAVE_DATA_DIR", (root / "share/mfwave").c_str(), 1);
  // This test runs from the build folder: the variable, beside the program, then the source tree.
  const std::vector<ShippedDataPlace> places = shippedDataPlaces();
  ASSERT_EQ(places.size(), 3u);
  EXPECT_EQ(places[0].origin, "MFWAVE_DATA_DIR");
  EXPECT_TRUE(fs::exists(fs::path(places[2].folder) / "data/scenes/lamb3d.toml"));
  EXPECT_TRUE(fs::equivalent(*findShippedFile("data/scenes/x.toml"), root / "share/mfwave/data/scenes/x.toml"));
  // What the variable lacks comes from the source tree.
  EXPECT_TRUE(fs::equivalent(*findShippedFile("data/scenes/lamb3d.toml"),
                             fs::path(places[2].folder) / "data/scenes/lamb3d.toml"));
}

TEST(ShippedData, TheMessageNamesEveryPlaceLooked) {
  DataDirVariable variable;
  const std::string text = describeShippedSearch("data/scenes/absent.toml");
  for (const ShippedDataPlace& place : shippedDataPlaces())
    EXPECT_NE(text.find((fs::path(place.folder) / "data/scenes/absent.toml").string()), std::string::npos) << text;
  EXPECT_NE(text.find("MFWAVE_DATA_DIR is not set"), std::string::npos) << text;
}

// A driver without --scene runs its shipped scene, data/scenes/<program>.toml or the one it names.
TEST(ShippedData, DriversDefaultToTheirShippedScene) {
  DataDirVariable variable;
  const fs::path root = installedTree("driver", "sample.toml");
  setenv("MFWAVE_DATA_DIR", (root / "share/mfwave").c_str(), 1);
  std::vector<std::string> words = {"tool", "--quiet"};
  std::vector<char*> argv;
  for (auto& w : words) argv.push_back(w.data());
  {
    DriverCommandLine cli("tool", "a test tool");  // data/scenes/tool.toml is nowhere
    testing::internal::CaptureStderr();
    EXPECT_EQ(cli.parse(2, argv.data()), 2);
    const std::string message = testing::internal::GetCapturedStderr();
    EXPECT_NE(message.find((root / "share/mfwave/data/scenes/tool.toml").string()), std::string::npos) << message;
  }
  {
    DriverCommandLine cli("tool", "a test tool");
    cli.setDefaultScene("sample.toml");
    EXPECT_FALSE(cli.parse(2, argv.data()).has_value());
    EXPECT_TRUE(fs::equivalent(cli.options().scenePath, root / "share/mfwave/data/scenes/sample.toml"));
  }
}

// A relative data path a scene names: as given when it exists, else from the shipped places.
TEST(ShippedData, DataFilesFallBackToTheShippedPlaces) {
  DataDirVariable variable;
  const fs::path root = installedTree("data-file", "x.toml");
  setenv("MFWAVE_DATA_DIR", (root / "share/mfwave").c_str(), 1);
  const fs::path here = fs::temp_directory_path() / "mfwave-shipped-here.csv";
  std::ofstream(here) << "a\n";
  EXPECT_EQ(resolveDataFile(here.string(), "study.table"), here.string());
  EXPECT_TRUE(fs::equivalent(resolveDataFile("data/scenes/x.toml", "study.table"),
                             root / "share/mfwave/data/scenes/x.toml"));
  try {
    resolveDataFile("data/reference/absent.csv", "study.table");
    FAIL() << "no error for a file that is nowhere";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "study.table");
    EXPECT_NE(std::string(e.what()).find((root / "share/mfwave/data/reference/absent.csv").string()),
              std::string::npos) << e.what();
  }
  EXPECT_THROW(resolveDataFile("/nonexistent/absolute.csv", "study.table"), InputError);
}

// A program's plot script: analysis/plot_<program>.py with '-' as '_' (here from the source tree).
TEST(ShippedData, FindsAProgramsPlotScript) {
  DataDirVariable variable;
  const auto lamb3d = findPlotScript("lamb3d");
  ASSERT_TRUE(lamb3d.has_value());
  EXPECT_EQ(fs::path(*lamb3d).filename(), "plot_lamb3d.py");
  const auto bars = findPlotScript("bar1d-sph");
  ASSERT_TRUE(bars.has_value());
  EXPECT_EQ(fs::path(*bars).filename(), "plot_bar1d_sph.py");
  EXPECT_FALSE(findPlotScript("tool").has_value());
}
