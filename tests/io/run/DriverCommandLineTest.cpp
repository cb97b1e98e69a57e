#include "io/run/DriverCommandLine.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <filesystem>
#include <memory>
#include <optional>
#include <utility>
#include <fstream>
#include <string>
#include <vector>

using namespace mfwave;

namespace {

// argv from a list of words (CLI11 wants char**).
struct Arguments {
  explicit Arguments(std::vector<std::string> words) : storage(std::move(words)) {
    for (auto& w : storage) pointers.push_back(w.data());
  }
  int argc() { return static_cast<int>(pointers.size()); }
  char** argv() { return pointers.data(); }
  std::vector<std::string> storage;
  std::vector<char*> pointers;
};

std::string sceneFile() {
  const auto path = std::filesystem::temp_directory_path() / "mfwave-cli-test.toml";
  std::ofstream(path) << "[scene]\nname = 'x'\n";
  return path.string();
}

}  // namespace

TEST(DriverCommandLine, ParsesTheSharedOptions) {
  DriverCommandLine cli("tool", "a test tool");
  Arguments args({"tool", "--scene", sceneFile(), "--set", "geometry.spacing=0.05", "--set", "output.vtk=true",
                  "--out", "somewhere", "--threads", "1", "--quiet"});
  EXPECT_FALSE(cli.parse(args.argc(), args.argv()).has_value());
  const DriverOptions& o = cli.options();
  EXPECT_EQ(o.scenePath, sceneFile());
  EXPECT_EQ(o.overrides, (std::vector<std::string>{"geometry.spacing=0.05", "output.vtk=true"}));
  EXPECT_EQ(o.outputFolder, "somewhere");
  EXPECT_EQ(o.threads, 1);
  EXPECT_TRUE(o.quiet);
  EXPECT_EQ(omp_get_max_threads(), 1);
}

TEST(DriverCommandLine, UsageErrorsAndMissingScenesExitWithTwo) {
  {
    DriverCommandLine cli("tool", "a test tool");
    Arguments args({"tool", "--frobnicate"});
    EXPECT_EQ(cli.parse(args.argc(), args.argv()), 2);
  }
  {
    DriverCommandLine cli("tool", "a test tool");
    Arguments args({"tool"});  // --scene is required
    EXPECT_EQ(cli.parse(args.argc(), args.argv()), 2);
  }
  {
    DriverCommandLine cli("tool", "a test tool");
    Arguments args({"tool", "--scene", "/nonexistent/scene.toml"});
    EXPECT_EQ(cli.parse(args.argc(), args.argv()), 2);
  }
}

TEST(DriverCommandLine, HelpListsTheOptionsAndTheSceneKeys) {
  DriverCommandLine cli("tool", "a test tool", "  geometry.spacing  number [m]  lattice spacing\n");
  const std::string help = cli.app().help();
  for (const char* word : {"--scene", "--set", "--out", "--threads", "--quiet", "--version", "geometry.spacing"})
    EXPECT_NE(help.find(word), std::string::npos) << word;
  testing::internal::CaptureStdout();
  Arguments args({"tool", "--help"});
  EXPECT_EQ(cli.parse(args.argc(), args.argv()), 0);
  EXPECT_NE(testing::internal::GetCapturedStdout().find("geometry.spacing"), std::string::npos);
  EXPECT_EQ(versionString("tool"),
            std::string("tool (mfwave ") + MFWAVE_EXPECTED_VERSION + ", git " + MFWAVE_EXPECTED_REVISION + ")");
}

// --checkpoint-every takes steps or seconds with an s; --restart stands in for --scene (the folder's
// scene.resolved.toml) and must name a folder.
TEST(DriverCommandLine, CheckpointAndRestartOptions) {
  const auto parse = [](std::vector<std::string> words) {
    auto cli = std::make_unique<DriverCommandLine>("tool", "a test tool");
    Arguments args(std::move(words));
    const std::optional<int> exit = cli->parse(args.argc(), args.argv());
    return std::make_pair(exit, cli->options());
  };
  auto [exit, steps] = parse({"tool", "--scene", sceneFile(), "--checkpoint-every", "500"});
  EXPECT_FALSE(exit.has_value());
  EXPECT_EQ(steps.checkpointSteps, 500);
  EXPECT_EQ(steps.checkpointSeconds, 0);
  auto [exit2, seconds] = parse({"tool", "--scene", sceneFile(), "--checkpoint-every", "90.5s"});
  EXPECT_FALSE(exit2.has_value());
  EXPECT_EQ(seconds.checkpointSteps, 0);
  EXPECT_EQ(seconds.checkpointSeconds, 90.5);
  for (const char* bad : {"0", "-5", "2.5", "s", "10x", "1e300", "nan", "10 s"})
    EXPECT_EQ(parse({"tool", "--scene", sceneFile(), "--checkpoint-every", bad}).first, 2) << bad;
  const std::string folder = std::filesystem::temp_directory_path().string();
  auto [exit3, restart] = parse({"tool", "--restart", folder});  // no --scene needed
  EXPECT_FALSE(exit3.has_value());
  EXPECT_EQ(restart.restartFolder, folder);
  EXPECT_EQ(parse({"tool", "--restart", folder + "/no-such-folder"}).first, 2);
}
