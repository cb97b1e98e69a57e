#pragma once
// The command line every driver and analysis tool shares:
//   --scene FILE, --set key.path=value (repeated), --out DIR, --threads N, --quiet, --help, --version,
//   --checkpoint-every N | Ts, --restart DIR, --check (validate only: prepareOutputFolder stops the
//   program there, io/run/SceneDriver.hpp).
// A driver may add its own options to app() before parse(). --help lists the options and, in its
// footer, the scene keys the driver reads. A driver whose scene is required runs its shipped scene,
// data/scenes/<program>.toml (or the one setDefaultScene names), when none is given: found beside
// the program or in the source tree (io/run/ShippedData), so an installed `lamb3d` runs the study.

#include <CLI/CLI.hpp>

#include <optional>
#include <string>
#include <vector>

namespace mfwave {

struct DriverOptions {
  std::string scenePath;               // --scene (empty if not given)
  std::vector<std::string> overrides;  // --set key.path=value, in order
  std::string outputFolder;            // --out (empty: the scene's output.folder)
  int threads = 0;                     // --threads (0: OpenMP's default)
  bool quiet = false;                  // --quiet: no progress, only the summary
  bool checkOnly = false;              // --check: validate the scene and the plan, run and write nothing
  // --checkpoint-every: a checkpoint every N steps ("500") or every T wall-clock seconds ("600s");
  // 0 for either when not given (then the scene's output.checkpoint_every / _seconds hold).
  long checkpointSteps = 0;
  double checkpointSeconds = 0;
  std::string restartFolder;           // --restart DIR (empty: a fresh run)
};

class DriverCommandLine {
 public:
  // `sceneKeys` is the text --help prints after the options (the scene keys the driver reads).
  DriverCommandLine(std::string program, std::string description, std::string sceneKeys = {},
                    bool sceneRequired = true);

  CLI::App& app() { return app_; }

  // The shipped scene (a file name in data/scenes) run when neither --scene nor --restart is given.
  void setDefaultScene(std::string fileName);

  // Parses argv. Returns an exit code when the program should stop now (0 after --help or
  // --version, 2 after a usage error, with the message printed), or nothing to carry on.
  // Applies --threads to OpenMP.
  std::optional<int> parse(int argc, char** argv);

  const DriverOptions& options() const { return options_; }
  const std::string& program() const { return program_; }

 private:
  std::string program_;
  bool sceneRequired_;
  std::string defaultScene_;
  std::string checkpointEvery_;  // as given, parsed after CLI11
  CLI::App app_;
  CLI::Option* sceneOption_ = nullptr;
  DriverOptions options_;
};

// The version string every driver prints: "<program> (mfwave <version>, git <revision>)".
std::string versionString(const std::string& program);

}  // namespace mfwave
