#include "io/run/DriverCommandLine.hpp"

#include <omp.h>

#include <iostream>

namespace mfwave {

#ifndef MFWAVE_VERSION
#define MFWAVE_VERSION "unknown"
#endif

std::string versionString(const std::string& program) { return program + " (mfwave " MFWAVE_VERSION ")"; }

DriverCommandLine::DriverCommandLine(std::string program, std::string description, std::string sceneKeys,
                                     bool sceneRequired)
    : program_(std::move(program)), app_(std::move(description), program_) {
  auto* scene = app_.add_option("--scene", options_.scenePath, "scene file (TOML); see docs/scenes.md")
                    ->check(CLI::ExistingFile);
  if (sceneRequired) scene->required();
  app_.add_option("--set", options_.overrides,
                  "override a scene key, e.g. --set geometry.spacing=0.05 (repeatable)")
      ->allow_extra_args(false)
      ->take_all();
  app_.add_option("--out", options_.outputFolder, "output folder (default: the scene's output.folder)");
  app_.add_option("--threads", options_.threads, "OpenMP threads (default: all cores)")->check(CLI::NonNegativeNumber);
  app_.add_flag("--quiet", options_.quiet, "no progress display; print only the summary");
  app_.set_version_flag("--version", versionString(program_));
  if (!sceneKeys.empty()) app_.footer("Scene keys read by " + program_ + ":\n" + sceneKeys);
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
  if (options_.threads > 0) omp_set_num_threads(options_.threads);
  return std::nullopt;
}

}  // namespace mfwave
