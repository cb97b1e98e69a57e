#include "core/BoundedRead.hpp"

#include "core/Error.hpp"

#include <filesystem>
#include <fstream>
#include <vector>

namespace mfwave {

std::string readBoundedFile(const std::string& path, std::size_t maxBytes, const std::string& key,
                            const std::string& what) {
  const std::string named = "cannot read " + what + " '" + path + "'";
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::is_regular_file(path, ec))
    throw InputError(key, named + ": " + (fs::exists(path, ec) ? "not a regular file" : "no such file"));
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(key, named);
  // Read in chunks up to maxBytes + 1: the reported size is not trusted (0 for /proc files).
  std::string text;
  std::vector<char> chunk(std::size_t(1) << 16);
  while (in) {
    in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
    text.append(chunk.data(), static_cast<std::size_t>(in.gcount()));
    if (text.size() > maxBytes)
      throw InputError(key, named + ": larger than the limit of " + std::to_string(maxBytes) + " bytes");
  }
  if (in.bad()) throw InputError(key, named);
  return text;
}

}  // namespace mfwave
