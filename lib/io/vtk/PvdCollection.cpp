#include "io/vtk/PvdCollection.hpp"

#include "core/AtomicFile.hpp"

#include <filesystem>

namespace mfwave {

namespace {

// File names go into an XML attribute: escape what would break it.
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

}  // namespace

PvdCollection::PvdCollection(std::string path) : path_(std::move(path)) {}

void PvdCollection::add(Real time, const std::string& file) {
  namespace fs = std::filesystem;
  const fs::path folder = fs::absolute(fs::path(path_)).lexically_normal().parent_path();
  const fs::path relative = fs::absolute(fs::path(file)).lexically_normal().lexically_proximate(folder);
  entries_.push_back({time, relative.generic_string()});
  rewrite();
}

void PvdCollection::rewrite() const {
  AtomicFile out(path_);  // precision 17: times round-trip exactly
  std::ostream& s = out.stream();
  s << "<?xml version=\"1.0\"?>\n"
    << "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
    << "  <Collection>\n";
  for (const auto& entry : entries_)
    s << "    <DataSet timestep=\"" << entry.time << "\" group=\"\" part=\"0\" file=\"" << xmlEscaped(entry.file)
      << "\"/>\n";
  s << "  </Collection>\n"
    << "</VTKFile>\n";
  out.commit();
}

}  // namespace mfwave
