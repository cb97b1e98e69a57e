#pragma once
// Face names of scene files ("-x", "+x", "-y", "+y", "-z", "+z", numbered as BoxFace) and
// component names ("x", "y", "z"), restricted to the scene's dimension.

#include "io/scene/SceneReader.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace mfwave {

// The 2 * dimension face names, in BoxFace order.
std::vector<std::string> faceNames(int dimension);
// "-x" -> 0 (BoxFace::MinusX), ..., nullopt when the name is not a face of that dimension.
std::optional<int> faceFromName(const std::string& name, int dimension);
std::string faceName(int face);
// The dimension's component names ("x", "y"[, "z"]).
std::vector<std::string> componentNames(int dimension);

// Reads a string array of face names at `path`, each valid for the dimension and named once
// (errors name the entry, "boundary[0].faces[1]"); returns the BoxFace numbers.
std::vector<int> readFaces(SceneReader& reader, const std::string& path, int dimension,
                           const std::vector<std::string>* fallback = nullptr);
// Reads a component name valid for the dimension; returns 0, 1 or 2.
int readComponent(SceneReader& reader, const std::string& path, int dimension);
// Bit mask (faceBit) of a list of faces.
std::uint8_t faceMaskOf(const std::vector<int>& faces);

}  // namespace mfwave
