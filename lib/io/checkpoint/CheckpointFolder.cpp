#include "io/checkpoint/CheckpointFolder.hpp"

#include "core/AtomicFile.hpp"
#include "core/BoundedRead.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <sstream>

namespace mfwave {
namespace {

namespace fs = std::filesystem;

constexpr const char* kPrefix = "checkpoint-";
constexpr const char* kExtension = ".mfwc";
// A checkpoint holds the whole state: allow any size a machine could hold.
constexpr std::size_t kMaxCheckpointBytes = std::size_t(1) << 40;

// The step of a checkpoint file's name, or -1 when the name is not one.
long long stepOfName(const std::string& name) {
  const std::string prefix = kPrefix, extension = kExtension;
  if (name.size() != prefix.size() + 12 + extension.size() || name.compare(0, prefix.size(), prefix) != 0 ||
      name.compare(name.size() - extension.size(), extension.size(), extension) != 0)
    return -1;
  long long step = 0;
  for (std::size_t i = prefix.size(); i < prefix.size() + 12; ++i) {
    if (name[i] < '0' || name[i] > '9') return -1;
    step = 10 * step + (name[i] - '0');
  }
  return step;
}

}  // namespace

std::vector<std::string> checkpointFiles(const std::string& folder) {
  std::vector<std::pair<long long, std::string>> found;
  std::error_code ec;
  for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
    const long long step = stepOfName(it->path().filename().string());
    if (step >= 0 && it->is_regular_file(ec)) found.emplace_back(step, it->path().string());
  }
  std::sort(found.begin(), found.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  std::vector<std::string> paths;
  for (const auto& f : found) paths.push_back(f.second);
  return paths;
}

std::string writeCheckpoint(const std::string& folder, const Checkpoint& checkpoint, int keep) {
  if (checkpoint.step < 0 || checkpoint.step > 999999999999LL)
    throw InputError("checkpoint", "step " + std::to_string(checkpoint.step) + " is outside 0 .. 999999999999");
  std::ostringstream name;
  name << kPrefix << std::setw(12) << std::setfill('0') << checkpoint.step << kExtension;
  const std::string path = (fs::path(folder) / name.str()).string();
  {
    AtomicFile file(path);
    const std::string bytes = encodeCheckpoint(checkpoint);
    file.stream().write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    file.commit();
  }
  const std::vector<std::string> files = checkpointFiles(folder);
  for (std::size_t i = static_cast<std::size_t>(std::max(keep, 1)); i < files.size(); ++i) {
    std::error_code ec;
    fs::remove(files[i], ec);
  }
  return path;
}

RestartPoint readNewestCheckpoint(const std::string& folder, const std::string& sceneDigest) {
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) throw InputError("--restart", "'" + folder + "' is not a folder");
  RestartPoint point;
  for (const std::string& path : checkpointFiles(folder)) {
    try {
      point.checkpoint = decodeCheckpoint(readBoundedFile(path, kMaxCheckpointBytes, "--restart", "the checkpoint"),
                                          path);
    } catch (const CorruptCheckpoint& e) {
      point.skipped.push_back(e.what());
      continue;
    }
    if (point.checkpoint.sceneDigest != sceneDigest)
      throw InputError("--restart", "checkpoint '" + path + "' belongs to another scene (digest " +
                                        point.checkpoint.sceneDigest + ", this scene's " + sceneDigest + ")");
    point.path = path;
    return point;
  }
  std::string why = "no whole checkpoint in '" + folder + "'";
  for (const std::string& s : point.skipped) why += "; skipped " + s;
  throw InputError("--restart", why);
}

}  // namespace mfwave
