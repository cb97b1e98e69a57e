#include "io/vtk/XmlText.hpp"

#include <filesystem>

namespace mfwave {

std::string xmlEscaped(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '"': out += "&quot;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string relativeToFolderOf(const std::string& anchor, const std::string& file) {
  namespace fs = std::filesystem;
  const fs::path folder = fs::absolute(fs::path(anchor)).lexically_normal().parent_path();
  return fs::absolute(fs::path(file)).lexically_normal().lexically_proximate(folder).generic_string();
}

}  // namespace mfwave
