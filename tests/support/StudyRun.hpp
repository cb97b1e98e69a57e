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

// What summary.json and the folder disagree on: each file in `folder` that the summary does not
// list, and each entry listed (without a wildcard) that is not there. An entry may carry a note
// in parentheses ("frame.pvd (5 frames)"); a listed "<base>.pvd" covers its frames
// "<base>_NNNNNN.vtp" and "<base>_*.png (N images)" its pictures. Empty when they agree.
inline std::vector<std::string> summaryDisagreements(const std::filesystem::path& folder) {
  namespace fs = std::filesystem;
  std::vector<std::string> listed;
  for (std::string entry : summaryFiles(folder / "summary.json")) {
    const std::size_t note = entry.find(" (");
    listed.push_back(note == std::string::npos ? entry : entry.substr(0, note));
  }
  const auto isListed = [&](const std::string& name) {
    for (const std::string& entry : listed) {
      if (entry == name) return true;
      const std::size_t star = entry.find('*');
      if (star != std::string::npos && name.size() >= entry.size() - 1 &&
          name.compare(0, star, entry, 0, star) == 0 &&
          name.compare(name.size() - (entry.size() - star - 1), std::string::npos, entry, star + 1) == 0)
        return true;
      // "<base>.pvd" lists its frames "<base>_NNNNNN.vtp"
      if (entry.size() > 4 && entry.compare(entry.size() - 4, 4, ".pvd") == 0) {
        const std::string base = entry.substr(0, entry.size() - 4) + "_";
        if (name.size() == base.size() + 10 && name.compare(0, base.size(), base) == 0 &&
            name.compare(name.size() - 4, 4, ".vtp") == 0)
          return true;
      }
    }
    return false;
  };
  std::vector<std::string> disagreements;
  for (const auto& file : fs::directory_iterator(folder))
    if (file.is_regular_file() && !isListed(file.path().filename().string()))
      disagreements.push_back("not listed: " + file.path().filename().string());
  for (const std::string& entry : listed)
    if (entry.find('*') == std::string::npos && !fs::exists(folder / entry))
      disagreements.push_back("listed, not written: " + entry);
  return disagreements;
}

}  // namespace mfwave::testing
