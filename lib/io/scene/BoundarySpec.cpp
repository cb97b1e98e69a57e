#include "io/scene/BoundarySpec.hpp"

#include "io/scene/Faces.hpp"
#include "io/scene/ScenePath.hpp"
#include "io/scene/TimeFunctionSpec.hpp"
#include "particles/BoxFace.hpp"

#include <algorithm>
#include <array>

namespace mfwave {

std::string boundaryTypeName(BoundaryType type) {
  switch (type) {
    case BoundaryType::Free: return "free";
    case BoundaryType::Fixed: return "fixed";
    case BoundaryType::Traction: return "traction";
    case BoundaryType::Displacement: return "displacement";
    case BoundaryType::Transmitting: return "transmitting";
    case BoundaryType::Symmetry: return "symmetry";
  }
  return "?";
}

std::vector<BoundarySpec> readBoundaries(SceneReader& reader, const GeometrySpec& geometry) {
  const int dimension = geometry.dimension;
  const auto d = static_cast<std::size_t>(dimension);
  std::vector<BoundarySpec> boundaries;
  std::array<std::string, 6> owner;  // entry that claimed each face
  const std::size_t count = reader.count("boundary");
  for (std::size_t i = 0; i < count; ++i) {
    const std::string entry = scene::indexPath("boundary", i);
    const auto key = [&](const char* name) { return scene::childPath(entry, name); };
    BoundarySpec b;
    b.faces = readFaces(reader, key("faces"), dimension);
    if (b.faces.empty()) reader.fail(key("faces"), "must name at least one face");
    for (std::size_t j = 0; j < b.faces.size(); ++j) {
      const int face = b.faces[j];
      const std::string at = scene::indexPath(key("faces"), j);
      const int axis = faceAxis(face);
      if (geometry.periodic[static_cast<std::size_t>(axis)])
        reader.fail(at, "face '" + faceName(face) + "' lies on axis " + axisName(axis) +
                            ", which is periodic (geometry.periodic[" + std::to_string(axis) +
                            "] = true): a periodic axis has no boundary faces");
      auto& claimed = owner[static_cast<std::size_t>(face)];
      if (!claimed.empty())
        reader.fail(at, "face '" + faceName(face) + "' already has a boundary condition in " + claimed +
                            "; each face may appear in at most one boundary entry");
      claimed = entry;
    }
    b.faceMask = faceMaskOf(b.faces);
    const std::string type = reader.string(key("type"));
    for (const BoundaryType t : {BoundaryType::Free, BoundaryType::Fixed, BoundaryType::Traction,
                                 BoundaryType::Displacement, BoundaryType::Transmitting, BoundaryType::Symmetry})
      if (type == boundaryTypeName(t)) b.type = t;
    if (b.type == BoundaryType::Traction) {
      b.traction = reader.numbers(key("traction"), d);
      b.timeFunction = readTimeFunction(reader, key("time_function"), false);
    } else if (b.type == BoundaryType::Displacement) {
      b.value = reader.numbers(key("value"), d, std::vector<Real>(d, 0.0));
      b.timeFunction = readTimeFunction(reader, key("time_function"), false);
    }
    if (b.type == BoundaryType::Symmetry) {
      // A mirror on both faces of one axis repeats the solid without end.
      for (std::size_t j = 0; j < b.faces.size(); ++j) {
        const int other = b.faces[j] ^ 1;
        const std::string& claimed = owner[static_cast<std::size_t>(other)];
        bool otherSymmetric = std::find(b.faces.begin(), b.faces.end(), other) != b.faces.end();
        for (const BoundarySpec& earlier : boundaries)
          otherSymmetric = otherSymmetric || (earlier.type == BoundaryType::Symmetry && (earlier.faceMask & faceBit(other)) != 0);
        if (otherSymmetric)
          reader.fail(scene::indexPath(key("faces"), j),
                      "faces '" + faceName(b.faces[j]) + "' and '" + faceName(other) + "' are both symmetry planes (" +
                          (claimed.empty() ? entry : claimed) + "): mirrors on both sides repeat the solid without "
                          "end; at most one symmetry face per axis");
      }
    }
    boundaries.push_back(std::move(b));
  }
  // Symmetry planes mirror the loads too: a condition on a face meeting a plane with a component
  // along the plane's normal is mirrored with that component reversed, which the methods do not
  // model on whole faces (surface-patch loads may: their images are reflected).
  const std::uint8_t symmetry = facesWith(boundaries, BoundaryType::Symmetry);
  for (std::size_t i = 0; i < boundaries.size(); ++i) {
    const BoundarySpec& b = boundaries[i];
    const std::vector<Real>& values = b.type == BoundaryType::Traction ? b.traction : b.value;
    if (b.type != BoundaryType::Traction && b.type != BoundaryType::Displacement) continue;
    for (int axis = 0; axis < dimension; ++axis) {
      if ((symmetry & (faceBit(2 * axis) | faceBit(2 * axis + 1))) == 0) continue;
      if (values[static_cast<std::size_t>(axis)] == 0) continue;
      for (const int face : b.faces)
        if (faceAxis(face) != axis)
          reader.fail(scene::indexPath(scene::childPath(scene::indexPath("boundary", i),
                                                        b.type == BoundaryType::Traction ? "traction" : "value"),
                                       static_cast<std::size_t>(axis)),
                      std::string("must be 0: face '") + faceName(face) + "' meets the symmetry plane normal to " +
                          axisName(axis) + ", where a symmetric field has no " + axisName(axis) +
                          " component (use a surface_patch load, whose image is mirrored)");
    }
  }
  return boundaries;
}

std::uint8_t facesWith(const std::vector<BoundarySpec>& boundaries, BoundaryType type) {
  std::uint8_t mask = 0;
  for (const auto& b : boundaries)
    if (b.type == type) mask = static_cast<std::uint8_t>(mask | b.faceMask);
  return mask;
}

}  // namespace mfwave
