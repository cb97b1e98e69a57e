#include "io/scene/ScenePath.hpp"

#include <cctype>

namespace mfwave::scene {
namespace {

bool isBareKeyCharacter(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '-';
}

}  // namespace

std::optional<std::vector<PathSegment>> parsePath(const std::string& path) {
  std::vector<PathSegment> segments;
  std::size_t i = 0;
  while (true) {
    PathSegment segment;
    while (i < path.size() && isBareKeyCharacter(path[i])) segment.key += path[i++];
    if (segment.key.empty()) return std::nullopt;
    if (i < path.size() && path[i] == '[') {
      ++i;
      std::string digits;
      while (i < path.size() && std::isdigit(static_cast<unsigned char>(path[i])) != 0) digits += path[i++];
      if (digits.empty() || digits.size() > 9 || i >= path.size() || path[i] != ']') return std::nullopt;
      ++i;
      segment.index = static_cast<std::size_t>(std::stoul(digits));
    }
    segments.push_back(std::move(segment));
    if (i == path.size()) return segments;
    if (path[i] != '.') return std::nullopt;
    ++i;
  }
}

std::string joinPath(const std::vector<PathSegment>& segments) {
  std::string path;
  for (const auto& segment : segments) {
    path = childPath(path, segment.key);
    if (segment.index) path = indexPath(path, *segment.index);
  }
  return path;
}

std::string patternOf(const std::string& path) {
  std::string pattern;
  for (std::size_t i = 0; i < path.size(); ++i) {
    pattern += path[i];
    if (path[i] == '[') {
      while (i + 1 < path.size() && path[i + 1] != ']') ++i;
    }
  }
  return pattern;
}

std::string childPath(const std::string& parent, const std::string& key) {
  return parent.empty() ? key : parent + "." + key;
}

std::string indexPath(const std::string& path, std::size_t index) {
  return path + "[" + std::to_string(index) + "]";
}

bool isWithin(const std::string& path, const std::string& ancestor) {
  if (path.compare(0, ancestor.size(), ancestor) != 0) return false;
  return path.size() == ancestor.size() || path[ancestor.size()] == '.' || path[ancestor.size()] == '[';
}

}  // namespace mfwave::scene
