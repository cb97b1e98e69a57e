#include "io/vtk/PvtpWriter.hpp"

#include "core/AtomicFile.hpp"
#include "core/Error.hpp"
#include "io/vtk/XmlText.hpp"

#include <cstdint>
#include <cstring>

namespace mfwave {

namespace {

// The pieces are written in the machine's byte order (VTK's default); the master says the same.
const char* byteOrder() {
  const std::uint16_t one = 1;
  unsigned char first = 0;
  std::memcpy(&first, &one, 1);
  return first == 1 ? "LittleEndian" : "BigEndian";
}

}  // namespace

void PvtpWriter::write(const std::vector<ParticleField>& fields, const std::vector<std::string>& pieces,
                       const std::string& path) {
  if (pieces.empty()) throw Error("writing VTK master '" + path + "': no pieces");
  // The same checks as a frame's fields, on a frame of no particles (the values are not needed).
  ParticleFrame<1> shape;
  const Coordinates<1> none;
  shape.positions = &none;
  for (const ParticleField& field : fields)
    shape.fields.push_back({field.name, field.components, field.kind, {}});
  checkFrame(shape);

  AtomicFile out(path);
  std::ostream& s = out.stream();
  s << "<?xml version=\"1.0\"?>\n"
    << "<VTKFile type=\"PPolyData\" version=\"1.0\" byte_order=\"" << byteOrder() << "\" header_type=\"UInt64\">\n"
    << "  <PPolyData GhostLevel=\"0\">\n"
    << "    <PPointData>\n";
  for (const ParticleField& field : fields)
    s << "      <PDataArray type=\"Float64\" Name=\"" << xmlEscaped(field.name) << "\" NumberOfComponents=\""
      << writtenComponents(field) << "\"/>\n";
  s << "    </PPointData>\n"
    << "    <PPoints>\n"
    << "      <PDataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\"/>\n"
    << "    </PPoints>\n";
  for (const std::string& piece : pieces)
    s << "    <Piece Source=\"" << xmlEscaped(relativeToFolderOf(path, piece)) << "\"/>\n";
  s << "  </PPolyData>\n"
    << "</VTKFile>\n";
  out.commit();
}

}  // namespace mfwave
