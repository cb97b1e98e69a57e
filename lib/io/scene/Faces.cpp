#include "io/scene/Faces.hpp"

#include "io/scene/Format.hpp"
#include "io/scene/ScenePath.hpp"
#include "particles/BoxFace.hpp"

#include <algorithm>

namespace mfwave {

std::vector<std::string> faceNames(int dimension) {
  static const char* const names[] = {"-x", "+x", "-y", "+y", "-z", "+z"};
  return std::vector<std::string>(names, names + 2 * dimension);
}

std::optional<int> faceFromName(const std::string& name, int dimension) {
  const auto names = faceNames(dimension);
  const auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end()) return std::nullopt;
  return static_cast<int>(it - names.begin());
}

std::string faceName(int face) { return faceNames(3).at(static_cast<std::size_t>(face)); }

std::vector<std::string> componentNames(int dimension) {
  static const char* const names[] = {"x", "y", "z"};
  return std::vector<std::string>(names, names + dimension);
}

std::vector<int> readFaces(SceneReader& reader, const std::string& path, int dimension,
                           const std::vector<std::string>* fallback) {
  const std::vector<std::string> names = fallback ? reader.strings(path, *fallback) : reader.strings(path);
  std::vector<int> faces;
  for (std::size_t i = 0; i < names.size(); ++i) {
    const auto face = faceFromName(names[i], dimension);
    if (!face)
      reader.fail(scene::indexPath(path, i), "'" + names[i] + "' is not a face of a " + std::to_string(dimension) +
                                                 "-D box; valid faces: " + scene::joinNames(faceNames(dimension)));
    if (std::find(faces.begin(), faces.end(), *face) != faces.end())
      reader.fail(scene::indexPath(path, i), "face '" + names[i] + "' is listed twice");
    faces.push_back(*face);
  }
  return faces;
}

int readComponent(SceneReader& reader, const std::string& path, int dimension) {
  const std::string name = reader.string(path);
  const auto names = componentNames(dimension);
  const auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end())
    reader.fail(path, "'" + name + "' is not a component of a " + std::to_string(dimension) +
                          "-D scene; valid: " + scene::joinNames(names));
  return static_cast<int>(it - names.begin());
}

std::uint8_t faceMaskOf(const std::vector<int>& faces) {
  std::uint8_t mask = 0;
  for (const int face : faces) mask = static_cast<std::uint8_t>(mask | faceBit(face));
  return mask;
}

}  // namespace mfwave
