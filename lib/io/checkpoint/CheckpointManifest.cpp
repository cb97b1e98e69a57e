#include "io/checkpoint/CheckpointManifest.hpp"

#include "core/AtomicFile.hpp"
#include "core/Error.hpp"

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>

namespace mfwave {
namespace {

constexpr const char* kManifestMagic = "mfwave-checkpoint-manifest";
constexpr int kManifestVersion = 1;

std::string pathOf(const std::string& folder) {
  return (std::filesystem::path(folder) / kCheckpointManifestName).string();
}

}  // namespace

std::string rankCheckpointFolderName(int rank, int ranks) {
  return "rank-" + std::to_string(rank) + "-of-" + std::to_string(ranks);
}

void writeCheckpointManifest(const std::string& folder, const CheckpointManifest& manifest) {
  AtomicFile file(pathOf(folder));
  std::ostream& out = file.stream();
  out << kManifestMagic << ' ' << kManifestVersion << '\n'
      << "ranks " << manifest.ranks << '\n'
      << "scene_digest " << manifest.sceneDigest << '\n'
      << "loop " << manifest.loop << '\n'
      << "step " << manifest.step << '\n'
      << "time " << std::setprecision(std::numeric_limits<Real>::max_digits10) << manifest.time << '\n'
      << "loop_ranks " << (manifest.rankZeroAlone ? "0" : "all") << '\n';
  for (const std::string& f : manifest.files) out << "file " << f << '\n';
  file.commit();
}

std::optional<CheckpointManifest> readCheckpointManifest(const std::string& folder) {
  const std::string path = pathOf(folder);
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return std::nullopt;
  std::ifstream in(path);
  if (!in) throw InputError("--restart", "cannot read '" + path + "'");
  CheckpointManifest manifest;
  std::string line;
  int number = 0;
  bool sawRanks = false, sawStep = false;
  while (std::getline(in, line)) {
    ++number;
    std::istringstream words(line);
    std::string key;
    words >> key;
    const auto bad = [&](const std::string& why) {
      return InputError("--restart", "'" + path + "' line " + std::to_string(number) + ": " + why);
    };
    if (number == 1) {
      int version = 0;
      if (key != kManifestMagic || !(words >> version)) throw bad("not a checkpoint manifest");
      if (version != kManifestVersion)
        throw bad("manifest version " + std::to_string(version) + ", this build reads " +
                  std::to_string(kManifestVersion));
      continue;
    }
    bool ok = true;
    if (key == "ranks") {
      ok = static_cast<bool>(words >> manifest.ranks) && manifest.ranks >= 1;
      sawRanks = true;
    } else if (key == "scene_digest") {
      // The digest has spaces ("crc32c <hex>, <n> bytes"): the rest of the line.
      std::getline(words >> std::ws, manifest.sceneDigest);
      ok = !manifest.sceneDigest.empty();
    } else if (key == "loop") {
      ok = static_cast<bool>(words >> manifest.loop);
    } else if (key == "step") {
      ok = static_cast<bool>(words >> manifest.step);
      sawStep = true;
    } else if (key == "time") {
      ok = static_cast<bool>(words >> manifest.time);
    } else if (key == "loop_ranks") {
      std::string who;
      ok = static_cast<bool>(words >> who) && (who == "all" || who == "0");
      manifest.rankZeroAlone = who == "0";
    } else if (key == "file") {
      std::string file;
      ok = static_cast<bool>(words >> file);
      manifest.files.push_back(file);
    } else if (!key.empty()) {
      throw bad("unknown key '" + key + "'");
    }
    if (!ok) throw bad("cannot read the value of '" + key + "'");
  }
  if (number == 0 || !sawRanks || !sawStep) throw InputError("--restart", "'" + path + "' is not a whole manifest");
  return manifest;
}

}  // namespace mfwave
