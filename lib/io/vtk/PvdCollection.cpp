#include "io/vtk/PvdCollection.hpp"

#include "core/AtomicFile.hpp"
#include "io/vtk/XmlText.hpp"

namespace mfwave {

PvdCollection::PvdCollection(std::string path) : path_(std::move(path)) {}

void PvdCollection::add(Real time, const std::string& file) {
  entries_.push_back({time, relativeToFolderOf(path_, file)});
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
