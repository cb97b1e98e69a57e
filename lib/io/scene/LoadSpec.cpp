#include "io/scene/LoadSpec.hpp"

#include "io/scene/Faces.hpp"
#include "io/scene/Format.hpp"
#include "io/scene/ScenePath.hpp"
#include "io/scene/TimeFunctionSpec.hpp"

#include <cmath>

namespace mfwave {

std::string loadTypeName(LoadType type) {
  switch (type) {
    case LoadType::PointForce:
      return "point_force";
    case LoadType::BodyForce:
      return "body_force";
    case LoadType::MomentTensor:
      return "moment_tensor";
    case LoadType::SurfaceTraction:
      return "surface_traction";
    default:
      return "surface_patch";
  }
}

namespace {

// A surface patch: on a face of the box, centred on it, with positive half-widths in the face
// and none along its normal; the patch may extend past the face's edges (it is clipped).
void readSurfacePatch(SceneReader& reader, const std::string& entry, const GeometrySpec& geometry, LoadSpec& load) {
  const auto d = static_cast<std::size_t>(geometry.dimension);
  const auto key = [&](const char* name) { return scene::childPath(entry, name); };
  const std::string faceText = reader.string(key("face"));
  const std::optional<int> face = faceFromName(faceText, geometry.dimension);
  if (!face) reader.fail(key("face"), "'" + faceText + "' is not a face of a " + std::to_string(d) + "-D box");
  load.face = *face;
  const auto axis = static_cast<std::size_t>(load.face / 2);
  const Real plane = load.face % 2 == 0 ? geometry.lower[axis] : geometry.upper[axis];
  load.centre = reader.numbers(key("centre"), d);
  const Real side = geometry.upper[axis] - geometry.lower[axis];
  if (std::abs(load.centre[axis] - plane) > 1e-9 * side)
    reader.fail(key("centre"), scene::formatPoint(load.centre) + " is not on face " + faceText + " (coordinate " +
                                   std::to_string(axis) + " must be " + scene::formatNumber(plane) + ")");
  load.centre[axis] = plane;
  if (!geometry.contains(load.centre))
    reader.fail(key("centre"), scene::formatPoint(load.centre) + " lies outside the geometry box " +
                                   geometry.describeBox());
  load.halfWidth = reader.numbers(key("half_width"), d);
  for (std::size_t a = 0; a < d; ++a) {
    const std::string at = scene::indexPath(key("half_width"), a);
    if (a == axis && load.halfWidth[a] != 0)
      reader.fail(at, "must be 0: axis " + std::to_string(a) + " is the normal of face " + faceText);
    if (a != axis && !(load.halfWidth[a] > 0))
      reader.fail(at, "must be positive, got " + scene::formatNumber(load.halfWidth[a]));
  }
  load.traction = reader.numbers(key("traction"), d);
}

}  // namespace

std::vector<LoadSpec> readLoads(SceneReader& reader, const GeometrySpec& geometry) {
  const auto d = static_cast<std::size_t>(geometry.dimension);
  std::vector<LoadSpec> loads;
  const std::size_t count = reader.count("load");
  for (std::size_t i = 0; i < count; ++i) {
    const std::string entry = scene::indexPath("load", i);
    const auto key = [&](const char* name) { return scene::childPath(entry, name); };
    LoadSpec load;
    const std::string type = reader.string(key("type"));
    load.type = type == "point_force"        ? LoadType::PointForce
                : type == "body_force"       ? LoadType::BodyForce
                : type == "moment_tensor"    ? LoadType::MomentTensor
                : type == "surface_traction" ? LoadType::SurfaceTraction
                                             : LoadType::SurfacePatch;
    if (load.type == LoadType::MomentTensor) {
      load.position = reader.numbers(key("position"), d);
      if (!geometry.contains(load.position))
        reader.fail(key("position"), scene::formatPoint(load.position) + " lies outside the geometry box " +
                                         geometry.describeBox());
      load.moment = reader.numbers(key("moment"), d == 2 ? 3 : 6);
      load.timeFunction = readTimeFunction(reader, key("time_function"), true);
    } else if (load.type == LoadType::SurfaceTraction) {
      load.surface = reader.string(key("surface"));
      load.centre = reader.numbers(key("centre"), d);
      load.radius = reader.number(key("radius"));
      const bool pressure = reader.has(key("pressure")), vector = reader.has(key("traction"));
      if (pressure == vector)
        reader.fail(key(pressure ? "traction" : "pressure"),
                    pressure ? "cannot be combined with pressure: give one" : "is missing: give pressure (along the inward normal) or traction (a vector)");
      if (pressure) load.pressure = reader.number(key("pressure"));
      else load.traction = reader.numbers(key("traction"), d);
      load.timeFunction = readTimeFunction(reader, key("time_function"), true);
    } else if (load.type == LoadType::SurfacePatch) {
      readSurfacePatch(reader, entry, geometry, load);
      load.timeFunction = readTimeFunction(reader, key("time_function"), true);
    } else if (load.type == LoadType::PointForce) {
      load.position = reader.numbers(key("position"), d);
      if (!geometry.contains(load.position))
        reader.fail(key("position"), scene::formatPoint(load.position) + " lies outside the geometry box " +
                                         geometry.describeBox());
      load.direction = reader.numbers(key("direction"), d);
      Real norm = 0;
      for (const Real c : load.direction) norm += c * c;
      norm = std::sqrt(norm);
      if (!(norm > 0)) reader.fail(key("direction"), "must not be the zero vector");
      for (Real& c : load.direction) c /= norm;
      load.amplitude = reader.number(key("amplitude"));
      load.timeFunction = readTimeFunction(reader, key("time_function"), true);
    } else {
      load.value = reader.numbers(key("value"), d);
      load.timeFunction = readTimeFunction(reader, key("time_function"), false);
    }
    loads.push_back(std::move(load));
  }
  return loads;
}

}  // namespace mfwave
