#include "io/run/ShippedData.hpp"

#include "io/run/BuildInfo.hpp"

#include "core/Error.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <system_error>

namespace mfwave {

namespace fs = std::filesystem;

namespace {

// Whether `path` lies inside `folder` (both made absolute and normal first).
bool isInside(const fs::path& path, const fs::path& folder) {
  if (folder.empty()) return false;
  const fs::path relative =
      fs::absolute(path).lexically_normal().lexically_relative(fs::absolute(folder).lexically_normal());
  return !relative.empty() && *relative.begin() != "..";
}

}  // namespace

std::string thisExecutable() {
  std::error_code error;
  const fs::path path = fs::read_symlink("/proc/self/exe", error);
  return error ? std::string() : path.string();
}

std::vector<ShippedDataPlace> shippedDataPlaces(const std::string& executable) {
  std::vector<ShippedDataPlace> places;
  if (const char* dataDir = std::getenv("MFWAVE_DATA_DIR"); dataDir && *dataDir)
    places.push_back({dataDir, "MFWAVE_DATA_DIR"});
  const fs::path exe = executable.empty() ? fs::path(thisExecutable()) : fs::path(executable);
  if (!exe.empty()) {
    places.push_back({(exe.parent_path() / ".." / "share" / "mfwave").lexically_normal().string(),
                      "beside the program " + exe.string()});
    // A program still in its build folder reads the source tree's data, so edits show at once.
    if (!mfwaveSourceFolder().empty() && isInside(exe, mfwaveBuildFolder()))
      places.push_back({mfwaveSourceFolder(), "the source tree of the build folder " + mfwaveBuildFolder()});
  }
  return places;
}

std::optional<std::string> findShippedFile(const std::string& relative, const std::string& executable) {
  for (const ShippedDataPlace& place : shippedDataPlaces(executable)) {
    const fs::path candidate = fs::path(place.folder) / relative;
    std::error_code error;
    if (fs::is_regular_file(candidate, error)) return candidate.string();
  }
  return std::nullopt;
}

std::string describeShippedSearch(const std::string& relative, const std::string& executable) {
  std::string text;
  for (const ShippedDataPlace& place : shippedDataPlaces(executable))
    text += "  " + (fs::path(place.folder) / relative).string() + " (" + place.origin + ")\n";
  if (!std::getenv("MFWAVE_DATA_DIR")) text += "  (MFWAVE_DATA_DIR is not set)\n";
  return text;
}

std::optional<std::string> findPlotScript(const std::string& program) {
  std::string name = program;
  std::replace(name.begin(), name.end(), '-', '_');
  return findShippedFile("analysis/plot_" + name + ".py");
}

std::string resolveDataFile(const std::string& path, const std::string& key) {
  std::error_code error;
  if (fs::is_regular_file(path, error)) return path;
  if (fs::path(path).is_relative())
    if (const std::optional<std::string> shipped = findShippedFile(path)) return *shipped;
  throw InputError(key, "cannot find '" + path + "': not from the working folder" +
                            (fs::path(path).is_relative() ? ", nor in:\n" + describeShippedSearch(path) : std::string()));
}

}  // namespace mfwave
