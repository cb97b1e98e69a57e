#pragma once
// Key paths of a scene: "geometry.spacing", "boundary[1].faces", "load[0].time_function.delay".
// A segment is a TOML bare key (letters, digits, '_' and '-'), optionally followed by an index
// into an array of tables. A path's pattern replaces every index by "[]"
// ("load[].time_function.delay"): the schema is keyed by patterns.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace mfwave::scene {

struct PathSegment {
  std::string key;
  std::optional<std::size_t> index;
};

// Splits a path into segments; returns nullopt when it is malformed (empty segment, a key with
// characters outside [A-Za-z0-9_-], a bad index).
std::optional<std::vector<PathSegment>> parsePath(const std::string& path);
std::string joinPath(const std::vector<PathSegment>& segments);
// "load[0].time_function.delay" -> "load[].time_function.delay".
std::string patternOf(const std::string& path);
// "a.b" + "c" -> "a.b.c"; "" + "c" -> "c".
std::string childPath(const std::string& parent, const std::string& key);
// "boundary[1].faces" + 2 -> "boundary[1].faces[2]".
std::string indexPath(const std::string& path, std::size_t index);
// True when `path` is `ancestor` or lies below it ("probe[0].name" below "probe[0]" and "probe").
bool isWithin(const std::string& path, const std::string& ancestor);

}  // namespace mfwave::scene
