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

// The (loop, step) of a checkpoint file's name, or (-1, -1) when the name is not one:
//   checkpoint-<loop, 4 digits>-<step, 12 digits>.mfwc
std::pair<long long, long long> numbersOfName(const std::string& name) {
  const std::string prefix = kPrefix, extension = kExtension;
  const std::pair<long long, long long> none{-1, -1};
  if (name.size() != prefix.size() + 4 + 1 + 12 + extension.size() || name.compare(0, prefix.size(), prefix) != 0 ||
      name.compare(name.size() - extension.size(), extension.size(), extension) != 0 || name[prefix.size() + 4] != '-')
    return none;
  const auto number = [&](std::size_t from, std::size_t digits) {
    long long value = 0;
    for (std::size_t i = from; i < from + digits; ++i) {
      if (name[i] < '0' || name[i] > '9') return -1LL;
      value = 10 * value + (name[i] - '0');
    }
    return value;
  };
  const long long loop = number(prefix.size(), 4), step = number(prefix.size() + 5, 12);
  if (loop < 0 || step < 0) return none;
  return {loop, step};
}

}  // namespace

std::vector<std::string> checkpointFiles(const std::string& folder, int loop) {
  std::vector<std::pair<std::pair<long long, long long>, std::string>> found;
  std::error_code ec;
  for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
    const auto numbers = numbersOfName(it->path().filename().string());
    if (numbers.first >= 0 && (loop < 0 || numbers.first == loop) && it->is_regular_file(ec))
      found.emplace_back(numbers, it->path().string());
  }
  std::sort(found.begin(), found.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  std::vector<std::string> paths;
  for (const auto& f : found) paths.push_back(f.second);
  return paths;
}

bool sameFolder(const std::string& a, const std::string& b) {
  std::error_code ec;
  return std::filesystem::equivalent(a, b, ec);
}

std::string checkpointFileName(int loop, long long step) {
  std::ostringstream name;
  name << kPrefix << std::setw(4) << std::setfill('0') << loop << '-' << std::setw(12) << step << kExtension;
  return name.str();
}

Checkpoint readCheckpointFile(const std::string& path) {
  return decodeCheckpoint(readBoundedFile(path, kMaxCheckpointBytes, "--restart", "the checkpoint"), path);
}

std::string writeCheckpoint(const std::string& folder, const Checkpoint& checkpoint, int loop, int keep) {
  if (checkpoint.step < 0 || checkpoint.step > 999999999999LL)
    throw InputError("checkpoint", "step " + std::to_string(checkpoint.step) + " is outside 0 .. 999999999999");
  if (loop < 0 || loop > 9999) throw InputError("checkpoint", "time loop " + std::to_string(loop) + " is outside 0 .. 9999");
  const std::string path = (fs::path(folder) / checkpointFileName(loop, checkpoint.step)).string();
  {
    AtomicFile file(path);
    const std::string bytes = encodeCheckpoint(checkpoint);
    file.stream().write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    file.commit();
  }
  const std::vector<std::string> files = checkpointFiles(folder, loop);
  for (std::size_t i = static_cast<std::size_t>(std::max(keep, 1)); i < files.size(); ++i) {
    std::error_code ec;
    fs::remove(files[i], ec);
  }
  return path;
}

RestartPoint readNewestCheckpoint(const std::string& folder, const std::string& sceneDigest, int loop) {
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) throw InputError("--restart", "'" + folder + "' is not a folder");
  RestartPoint point;
  for (const std::string& path : checkpointFiles(folder, loop)) {
    try {
      point.checkpoint = readCheckpointFile(path);
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
