#pragma once
// Test helper for study tests: runs a driver as a user would (its own process, output to a log),
// and reads the numbers of the summary.json it writes.

#include <nlohmann/json.hpp>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace mfwave::testing {

struct StudyOutcome {
  bool exited;
  int exitCode;
  std::string log;
};

// Runs `executable --quiet --scene <scene> <arguments>`, stdout and stderr to a log named after
// `logName` in the temporary folder.
inline StudyOutcome runStudy(const std::string& executable, const std::string& scene, const std::string& arguments,
                             const std::string& logName) {
  namespace fs = std::filesystem;
  const fs::path log = fs::temp_directory_path() / ("mfwave-" + logName + ".log");
  const std::string command =
      executable + " --quiet --scene " + scene + " " + arguments + " > " + log.string() + " 2>&1";
  const int status = std::system(command.c_str());
  std::ifstream in(log);
  std::stringstream text;
  text << in.rdbuf();
  return {WIFEXITED(status) != 0, WIFEXITED(status) ? WEXITSTATUS(status) : -1, text.str()};
}

// The named numbers of one section ("errors" or "figures") of a summary.json, or of both when
// `section` is null. Entries that are not numbers (null for NaN) are left out.
inline std::map<std::string, double> summaryNumbers(const std::filesystem::path& summaryPath,
                                                    const char* section = nullptr) {
  const nlohmann::json summary = nlohmann::json::parse(std::ifstream(summaryPath));
  std::map<std::string, double> found;
  for (const char* name : {"errors", "figures"}) {
    if (section != nullptr && std::string(section) != name) continue;
    for (const auto& [key, value] : summary[name].items())
      if (value.is_number()) found[key] = value.get<double>();
  }
  return found;
}

// The files a summary.json lists (relative to its folder, as the driver wrote them).
inline std::vector<std::string> summaryFiles(const std::filesystem::path& summaryPath) {
  const nlohmann::json summary = nlohmann::json::parse(std::ifstream(summaryPath));
  return summary["files"].get<std::vector<std::string>>();
}

}  // namespace mfwave::testing
