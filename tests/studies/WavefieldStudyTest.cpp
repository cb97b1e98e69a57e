// Runs the wavefield driver as a user would: the sample 3-D scene writes its frames, collection,
// probes and summary; every malformed scene of tests/io/scene/malformed fails with exit code 2
// and names its key, and none crashes.
#include "support/StudyRun.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sys/wait.h>

#include <cstdlib>
#include <unistd.h>
#include <cstdio>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

struct WavefieldOutcome {
  bool exited;     // false: killed by a signal (a crash)
  int exitCode;
  std::string log;  // standard output and error
};

WavefieldOutcome runProgram(const std::string& executable, const std::string& arguments, const std::string& name,
                   const std::string& prefix = "") {
  const fs::path log = fs::temp_directory_path() / ("mfwave-wavefield-" + name + ".log");
  const std::string command = prefix + executable + " --quiet " + arguments + " > " + log.string() + " 2>&1";
  const int status = std::system(command.c_str());
  std::ifstream in(log);
  std::stringstream text;
  text << in.rdbuf();
  return {WIFEXITED(status) != 0, WIFEXITED(status) ? WEXITSTATUS(status) : -1, text.str()};
}

WavefieldOutcome runWavefield(const std::string& arguments, const std::string& name, const std::string& prefix = "") {
  return runProgram(WAVEFIELD_EXECUTABLE, arguments, name, prefix);
}

std::string firstLineValue(const fs::path& file, const std::string& marker) {
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line))
    if (line.rfind(marker, 0) == 0) return line.substr(marker.size());
  return "";
}

}  // namespace

// Without --scene a driver runs its shipped scene (wavefield: block-ricker.toml), found from the
// build folder in the source tree, and its summary names the build.
TEST(WavefieldStudy, WithoutASceneRunsTheShippedOne) {
  const fs::path out = fs::temp_directory_path() / "mfwave-wavefield-shipped";
  fs::remove_all(out);
  const WavefieldOutcome run = runWavefield("--set integrator.end_time=0.1 --out " + out.string(), "shipped",
                                            "env -u MFWAVE_DATA_DIR ");
  ASSERT_TRUE(run.exited && run.exitCode == 0) << run.log;
  const nlohmann::json summary = nlohmann::json::parse(std::ifstream(out / "summary.json"));
  EXPECT_EQ(summary["scene"], "block-ricker");
  EXPECT_EQ(summary["mfwave_version"], MFWAVE_EXPECTED_VERSION);
  EXPECT_EQ(summary["git_revision"], MFWAVE_EXPECTED_REVISION);
  EXPECT_EQ(firstLineValue(out / "scene.resolved.toml", "# Resolved scene: "),
            fs::path(std::string(SCENES_FOLDER) + "/block-ricker.toml").lexically_normal().string() +
                " with every override applied and every default filled in.");
}

TEST(WavefieldStudy, SampleBlockSceneWritesFramesProbesAndSummary) {
  const fs::path out = fs::temp_directory_path() / "mfwave-wavefield-block";
  fs::remove_all(out);
  // A shorter run of the README's sample scene: the pulse has left the source by t = 0.6.
  const WavefieldOutcome run = runWavefield(std::string("--scene ") + SCENES_FOLDER + "/block-ricker.toml --set integrator.end_time=0.6 " +
                                       "--out " + out.string(),
                                   "block");
  ASSERT_TRUE(run.exited && run.exitCode == 0) << run.log;
  EXPECT_EQ(mfwave::testing::summaryDisagreements(out), std::vector<std::string>{});  // every output listed
  EXPECT_TRUE(fs::exists(out / "frame.pvd"));
  EXPECT_TRUE(fs::exists(out / "frame_000000.vtp"));
  EXPECT_TRUE(fs::exists(out / "frame_000002.vtp"));  // steps 0, 25, 50 of 72
  EXPECT_TRUE(fs::exists(out / "probes.csv"));
  EXPECT_TRUE(fs::exists(out / "scene.resolved.toml"));
  const nlohmann::json summary = nlohmann::json::parse(std::ifstream(out / "summary.json"));
  EXPECT_EQ(summary["particles"], 9261);
  EXPECT_EQ(summary["steps"], 72);  // dt = 0.5 x stable step 0.0167, landing on t = 0.6
  EXPECT_GT(summary["particle_steps_per_second"].get<double>(), 0);
  // The probe above the source has seen the pulse: its peak velocity is well above round-off.
  std::ifstream probes(out / "probes.csv");
  std::string header, line;
  std::getline(probes, header);
  EXPECT_EQ(header, "time [s],centre v [m/s],above v [m/s]");
  double peakAbove = 0;
  while (std::getline(probes, line)) peakAbove = std::max(peakAbove, std::abs(std::stod(line.substr(line.rfind(',') + 1))));
  EXPECT_GT(peakAbove, 1e-3);
}

TEST(WavefieldStudy, PngFramesUnderXvfb) {
  if (std::system("command -v xvfb-run > /dev/null 2>&1") != 0) GTEST_SKIP() << "xvfb-run is not installed";
  const fs::path out = fs::temp_directory_path() / "mfwave-wavefield-png";
  fs::remove_all(out);
  const WavefieldOutcome run = runWavefield(std::string("--scene ") + SCENES_FOLDER +
                                       "/block-ricker.toml --set integrator.end_time=0.3 --set geometry.spacing=0.1 " +
                                       "--out " + out.string(),
                                   "png", "xvfb-run -a -s '-screen 0 1280x1024x24' ");
  ASSERT_TRUE(run.exited && run.exitCode == 0) << run.log;
  EXPECT_EQ(mfwave::testing::summaryDisagreements(out), std::vector<std::string>{});  // every output listed
  EXPECT_TRUE(fs::exists(out / "frame_000000.png")) << run.log;
  EXPECT_GT(fs::file_size(out / "frame_000000.png"), 10000u);
}

TEST(WavefieldStudy, WithoutADisplayTheRunSaysWhyNoPngWasMade) {
  const fs::path out = fs::temp_directory_path() / "mfwave-wavefield-nodisplay";
  fs::remove_all(out);
  const WavefieldOutcome run = runWavefield(std::string("--scene ") + SCENES_FOLDER +
                                       "/block-ricker.toml --set integrator.end_time=0.1 --set geometry.spacing=0.1 " +
                                       "--out " + out.string(),
                                   "nodisplay", "env -u DISPLAY ");
  ASSERT_TRUE(run.exited && run.exitCode == 0) << run.log;
  EXPECT_EQ(mfwave::testing::summaryDisagreements(out), std::vector<std::string>{});  // every output listed
  EXPECT_NE(run.log.find("no PNG frames"), std::string::npos) << run.log;
  EXPECT_TRUE(fs::exists(out / "frame_000000.vtp"));
  EXPECT_FALSE(fs::exists(out / "frame_000000.png"));
}

TEST(WavefieldStudy, AnUnstableTimeStepIsRefusedBeforeAnyWork) {
  // The sample scene with a fixed step of 0.02, above the stable step dx / (c sqrt 3) = 0.0167.
  const fs::path scene = fs::temp_directory_path() / "mfwave-unstable-step.toml";
  {
    std::ifstream in(std::string(SCENES_FOLDER) + "/block-ricker.toml");
    std::stringstream text;
    text << in.rdbuf();
    std::string content = text.str();
    content.replace(content.find("cfl = 0.5"), 9, "time_step = 0.02");
    std::ofstream(scene) << content;
  }
  const fs::path out = fs::temp_directory_path() / "mfwave-wavefield-unstable";
  fs::remove_all(out);
  const WavefieldOutcome run = runWavefield("--scene " + scene.string() + " --out " + out.string(), "unstable");
  ASSERT_TRUE(run.exited);
  EXPECT_EQ(run.exitCode, 2) << run.log;
  EXPECT_NE(run.log.find("integrator.time_step: the step 0.02 exceeds the central_difference limit 2 / omega_max = "
                         "0.0166"), std::string::npos) << run.log;
  EXPECT_FALSE(fs::exists(out / "summary.json"));
  // The same through cfl, and for an ARKODE table at its own limit (classic RK4: 2 sqrt 2 / omega_max).
  for (const char* sets : {" --set integrator.cfl=5", " --set integrator.name=arkode --set integrator.cfl=1.5"}) {
    const WavefieldOutcome over = runWavefield("--scene " + std::string(SCENES_FOLDER) + "/block-ricker.toml" + sets +
                                          " --out " + out.string(), "unstable-cfl");
    ASSERT_TRUE(over.exited);
    EXPECT_EQ(over.exitCode, 2) << over.log;
    EXPECT_NE(over.log.find("integrator.cfl: the step"), std::string::npos) << over.log;
  }
}

// Hostile input: a scene whose only line is a dotted key of 200,000 parts used to kill every driver
// with SIGSEGV inside the TOML reader (its recursion overflowed the stack); now a syntax error.
TEST(WavefieldStudy, ADeepDottedKeyIsASyntaxErrorNotACrash) {
  const fs::path dir = fs::temp_directory_path() / "mfwave-deep-key";
  fs::remove_all(dir);
  fs::create_directories(dir);
  {
    std::ofstream scene(dir / "deep.toml");
    for (int k = 0; k < 200000; ++k) scene << "a.";
    scene << "a = 1\n";
  }
  const WavefieldOutcome run =
      runWavefield("--scene " + (dir / "deep.toml").string() + " --out " + (dir / "out").string(), "deep-key");
  ASSERT_TRUE(run.exited) << "crashed: " << run.log;
  EXPECT_EQ(run.exitCode, 2) << run.log;
  EXPECT_NE(run.log.find("deep.toml:1:1: (syntax): a dotted key of more than 64 parts"), std::string::npos) << run.log;
  EXPECT_FALSE(fs::exists(dir / "out"));
}

// Sizes no machine runs (a resolution of 1e12, an end time of 1e300) are typos: refused before any
// work naming the key, not cast into an overflowed int or step count.
TEST(WavefieldStudy, ResolutionsAndRunsBeyondAnyMachineAreRefusedNamingTheKey) {
  const std::string scenes = std::string(SCENES_FOLDER) + "/";
  const struct {
    const char* executable;
    std::string arguments;
    const char* expected;
  } cases[] = {
      {WAVE1D_EXECUTABLE, "--scene " + scenes + "wave1d.toml --set 'study.cells=[1e12]'", "study.cells: at most 1e8"},
      {BAR1D_EXECUTABLE, "--scene " + scenes + "bar1d.toml --set 'study.nodes=[1e12]'", "study.nodes: at most 20000"},
      {PLANE2D_EXECUTABLE, "--scene " + scenes + "plane2d.toml --set 'study.cells=[1e12]'", "study.cells: at most 2000"},
      {LAMB3D_EXECUTABLE, "--scene " + scenes + "lamb3d.toml --set 'study.spacings=[0.5]' --set integrator.end_time=1e300",
       "integrator.end_time: 1e300 s at a step of"},
      {WAVEFIELD_EXECUTABLE, "--scene " + scenes + "block-ricker.toml --set integrator.end_time=1e300",
       "more than 1e12 is refused"},
      // 3.4e8 particles: about 103 GiB even as lattice stencils, refused before any case; with the
      // sparse matrices about 2.6 TB.
      {LAMB3D_EXECUTABLE, "--scene " + scenes + "lamb3d.toml --set 'study.spacings=[0.5, 0.01]'",
       "study.spacings: case galerkin_0.01 (dx = 0.01) needs about 103 GiB"},
      {LAMB3D_EXECUTABLE, "--scene " + scenes + "lamb3d.toml --set 'study.spacings=[0.5, 0.01]' --set method.operator=sparse",
       "study.spacings: case galerkin_0.01 (dx = 0.01) needs about 2628 GiB"},
      // The other methods' measured costs per particle (io/run/MemoryGuard).
      {LAMB3D_EXECUTABLE, "--scene " + scenes + "lamb3d.toml --set method.name=updated_lagrangian_sph --set 'study.spacings=[0.5, 0.02]'",
       "study.spacings: case ulsph_0.02 (dx = 0.02) needs about 330 GiB (43243551 particles at about 8192 bytes each"},
      {PLANE2D_EXECUTABLE, "--scene " + scenes + "plane2d.toml --set 'study.cells=[1500]'",
       "study.cells: 1500 cells per side needs about 68.8 GiB (2253001 particles at about 32768 bytes each"},
  };
  const fs::path out = fs::temp_directory_path() / "mfwave-beyond-any-machine";
  for (const auto& c : cases) {
    fs::remove_all(out);
    const WavefieldOutcome run = runProgram(c.executable, c.arguments + " --out " + out.string(), "beyond");
    ASSERT_TRUE(run.exited) << "crashed: " << c.arguments << "\n" << run.log;
    EXPECT_EQ(run.exitCode, 2) << c.arguments << "\n" << run.log;
    EXPECT_NE(run.log.find(c.expected), std::string::npos) << c.arguments << "\n" << run.log;
    EXPECT_FALSE(fs::exists(out / "summary.json"));
  }
}

// An output folder that cannot be made (a file of that name, a path under a file) is an error of the
// environment (exit 1) naming the path and where it came from, before any work; not an internal error.
TEST(WavefieldStudy, AnOutputFolderThatCannotBeMadeIsSaidWithItsPath) {
  const fs::path file = fs::temp_directory_path() / "mfwave-out-is-a-file";
  fs::remove_all(file);
  std::ofstream(file) << "not a folder\n";
  const std::string scene = "--scene " + std::string(SCENES_FOLDER) + "/block-ricker.toml";
  const WavefieldOutcome out = runWavefield(scene + " --out " + file.string(), "out-file");
  ASSERT_TRUE(out.exited) << out.log;
  EXPECT_EQ(out.exitCode, 1) << out.log;
  EXPECT_NE(out.log.find("wavefield: error: --out: cannot make the output folder '" + file.string() + "'"),
            std::string::npos) << out.log;
  const WavefieldOutcome folder = runWavefield(scene + " --set output.folder=" + (file / "below").string(), "out-below-file");
  EXPECT_EQ(folder.exitCode, 1) << folder.log;
  EXPECT_NE(folder.log.find("output.folder: cannot make the output folder"), std::string::npos) << folder.log;
}

// A file that cannot be written whole (here a 20 KiB file size limit, as a full disk or a quota
// would) stops the run with exit 1 naming the file and why; no temporary and no partial file stays.
TEST(WavefieldStudy, AFileThatCannotBeWrittenWholeStopsTheRunNamingIt) {
  const fs::path out = fs::temp_directory_path() / "mfwave-wavefield-fsize";
  fs::remove_all(out);
  const WavefieldOutcome run = runWavefield("--scene " + std::string(SCENES_FOLDER) + "/block-ricker.toml --out " + out.string(),
                                   "fsize", "ulimit -f 20; ");
  ASSERT_TRUE(run.exited) << "killed (SIGXFSZ?): " << run.log;
  EXPECT_EQ(run.exitCode, 1) << run.log;
  EXPECT_NE(run.log.find("writing VTK frame '" + (out / "frame_000000.vtp").string() + "' failed: File too large"),
            std::string::npos) << run.log;
  for (const auto& entry : fs::directory_iterator(out))
    EXPECT_EQ(entry.path().filename(), "scene.resolved.toml") << "left behind: " << entry.path();
}

// SIGTERM while the run steps: it ends after the current step, every output of the steps taken is
// written, summary.json says where the run stopped, and the exit status is 128 + 15.
TEST(WavefieldStudy, ASigtermEndsTheRunCleanlyWithItsOutputs) {
  const fs::path out = fs::temp_directory_path() / "mfwave-wavefield-sigterm";
  fs::remove_all(out);
  const fs::path log = fs::temp_directory_path() / "mfwave-wavefield-sigterm.log";
  // A run of about 10^6 steps, so the signal surely arrives while it steps; frames every 20 steps
  // tell that it does.
  const std::string command = "exec " + std::string(WAVEFIELD_EXECUTABLE) + " --quiet --scene " + SCENES_FOLDER +
                              "/block-ricker.toml --set integrator.end_time=15000 --set output.every=20 --out " +
                              out.string() + " > " + log.string() + " 2>&1";
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {  // the child becomes the driver itself (exec), so the signal and the status are its own
    execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  for (int k = 0; k < 600 && !fs::exists(out / "frame_000002.vtp"); ++k) usleep(50000);
  const bool stepping = fs::exists(out / "frame_000002.vtp");
  kill(pid, SIGTERM);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(stepping) << "the run did not start stepping";
  ASSERT_TRUE(WIFEXITED(status)) << "killed by the signal instead of stopping cleanly";
  EXPECT_EQ(WEXITSTATUS(status), 128 + SIGTERM);
  std::ifstream in(log);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_NE(text.str().find("wavefield: interrupted by SIGTERM"), std::string::npos) << text.str();
  ASSERT_TRUE(fs::exists(out / "summary.json")) << text.str();
  const nlohmann::json summary = nlohmann::json::parse(std::ifstream(out / "summary.json"));
  EXPECT_EQ(summary["interrupted"], "SIGTERM");
  const double reached = summary["simulated_time"];
  EXPECT_GT(reached, 0);
  EXPECT_LT(reached, 15000);
  EXPECT_TRUE(fs::exists(out / "probes.csv"));
  EXPECT_TRUE(fs::exists(out / "frame.pvd"));
}

class MalformedScene : public ::testing::TestWithParam<std::string> {};

TEST_P(MalformedScene, FailsWithExitCodeTwoAndNamesTheKey) {
  const fs::path scene = GetParam();
  const std::string key = firstLineValue(scene, "# expect-key: ");
  ASSERT_FALSE(key.empty()) << scene;
  const fs::path out = fs::temp_directory_path() / ("mfwave-malformed-" + scene.stem().string());
  fs::remove_all(out);
  const WavefieldOutcome run = runWavefield("--scene " + scene.string() + " --out " + out.string(), scene.stem().string());
  ASSERT_TRUE(run.exited) << "crashed: " << run.log;
  EXPECT_EQ(run.exitCode, 2) << run.log;
  EXPECT_NE(run.log.find(key), std::string::npos) << "expected key '" << key << "' in: " << run.log;
  EXPECT_FALSE(fs::exists(out / "summary.json"));  // no work, no output
}

std::vector<std::string> malformedScenes() {
  std::vector<std::string> files;
  for (const auto& entry : fs::directory_iterator(MALFORMED_FOLDER))
    if (entry.path().extension() == ".toml") files.push_back(entry.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

INSTANTIATE_TEST_SUITE_P(EveryFile, MalformedScene, ::testing::ValuesIn(malformedScenes()),
                         [](const auto& parameter) {
                           std::string name = fs::path(parameter.param).stem().string();
                           for (char& c : name)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return "scene_" + name;
                         });
