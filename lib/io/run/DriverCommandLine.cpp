#include "io/run/DriverCommandLine.hpp"

#include "io/run/BuildInfo.hpp"
#include "io/run/ShippedData.hpp"

#include <omp.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>

namespace mfwave {

namespace {

// True unless a launcher (mpirun: Open MPI, PMI or PMIx) started this process as a rank other than 0.
bool firstProcessOfLauncher() {
  for (const char* name : {"OMPI_COMM_WORLD_RANK", "PMIX_RANK", "PMI_RANK"})
    if (const char* rank = std::getenv(name)) return std::string(rank) == "0";
  return true;
}

}  // namespace

std::string versionString(const std::string& program) {
  return program + " (mfwave " + mfwaveVersion() + ", git " + mfwaveGitRevision() + ")";
}

DriverCommandLine::DriverCommandLine(std::string program, std::string description, std::string sceneKeys,
                                     bool sceneRequired)
    : program_(std::move(program)),
      sceneRequired_(sceneRequired),
      defaultScene_(program_ + ".toml"),
      app_(std::move(description), program_) {
  sceneOption_ = app_.add_option("--scene", options_.scenePath)->check(CLI::ExistingFile);
  setDefaultScene(defaultScene_);
  app_.add_option("--set", options_.overrides,
                  "override a scene key, e.g. --set geometry.spacing=0.05 (repeatable)")
      ->allow_extra_args(false)
      ->take_all();
  app_.add_option("--out", options_.outputFolder, "output folder (default: the scene's output.folder)");
  app_.add_option("--threads", options_.threads, "OpenMP threads (default: all cores)")->check(CLI::NonNegativeNumber);
  app_.add_flag("--quiet", options_.quiet, "no progress display; print only the summary");
  app_.add_flag("--check", options_.checkOnly,
                "read and validate the scene and the study's plan, then stop: nothing is run or written (exit 0 "
                "when valid, 2 naming the key when not)");
  app_.add_option("--checkpoint-every", checkpointEvery_,
                  "write a checkpoint every N steps (e.g. 500) or every T wall-clock seconds (e.g. 600s) into the "
                  "output folder; overrides output.checkpoint_every / output.checkpoint_seconds");
  app_.add_option("--restart", options_.restartFolder,
                  "go on from the newest whole checkpoint in this output folder (with its scene.resolved.toml "
                  "unless --scene is given; the outputs go there unless --out is given)")
      ->check(CLI::ExistingDirectory);
  app_.set_version_flag("--version", versionString(program_));
  if (!sceneKeys.empty()) app_.footer("Scene keys read by " + program_ + ":\n" + sceneKeys);
}

void DriverCommandLine::setDefaultScene(std::string fileName) {
  defaultScene_ = std::move(fileName);
  sceneOption_->description(std::string("scene file (TOML); see docs/scenes.md") +
                            (sceneRequired_ ? " (default: the shipped data/scenes/" + defaultScene_ +
                                                  "; with --restart, the scene of the folder it goes on from)"
                                            : ""));
}

std::optional<int> DriverCommandLine::parse(int argc, char** argv) {
  try {
    app_.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app_.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app_.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << program_ << ": " << e.what() << "\n(run " << program_ << " --help for the options)\n";
    return 2;
  }
  const auto usage = [&](const std::string& message) {
    std::cerr << program_ << ": " << message << "\n(run " << program_ << " --help for the options)\n";
    return 2;
  };
  if (sceneRequired_ && options_.scenePath.empty() && options_.restartFolder.empty()) {
    const std::string relative = "data/scenes/" + defaultScene_;
    const std::optional<std::string> shipped = findShippedFile(relative);
    if (!shipped)
      return usage("no --scene given, and the shipped scene " + relative + " is in none of the places looked:\n" +
                   describeShippedSearch(relative) +
                   "give --scene FILE, or set MFWAVE_DATA_DIR to the folder holding data/scenes");
    options_.scenePath = *shipped;
    // Said once under mpirun: by the launcher's first process (MPI has not started yet).
    if (!options_.quiet && firstProcessOfLauncher())
      std::cout << program_ << ": no --scene given: the shipped scene " << *shipped << '\n';
  }
  if (!checkpointEvery_.empty()) {
    const bool seconds = checkpointEvery_.back() == 's';
    const std::string number = seconds ? checkpointEvery_.substr(0, checkpointEvery_.size() - 1) : checkpointEvery_;
    std::size_t used = 0;
    double value = 0;
    try {
      value = std::stod(number, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    const bool whole = value == std::floor(value) && value <= 1e15;
    if (used == 0 || used != number.size() || !(value > 0) || !std::isfinite(value) || (!seconds && !whole))
      return usage("--checkpoint-every: expected a whole number of steps (500) or seconds with an s (600s), got '" +
                   checkpointEvery_ + "'");
    if (seconds)
      options_.checkpointSeconds = value;
    else
      options_.checkpointSteps = static_cast<long>(value);
  }
  if (options_.threads > 0) omp_set_num_threads(options_.threads);
  return std::nullopt;
}

}  // namespace mfwave
