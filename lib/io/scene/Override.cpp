#include "io/scene/Override.hpp"

#include "io/scene/KeyDepth.hpp"
#include "io/scene/SceneError.hpp"
#include "io/scene/ScenePath.hpp"

namespace mfwave {
namespace {

// The assignment as the message quotes it: a hostile one can be megabytes long.
std::string quoted(const std::string& assignment) {
  constexpr std::size_t shown = 80;
  if (assignment.size() <= shown) return "'" + assignment + "'";
  return "'" + assignment.substr(0, shown) + "...' (" + std::to_string(assignment.size()) + " characters)";
}

[[noreturn]] void malformed(const std::string& assignment, const std::string& problem) {
  throw SceneError("", "--set", "malformed override " + quoted(assignment) + ": " + problem);
}

std::string trim(const std::string& text) {
  const auto begin = text.find_first_not_of(" \t");
  if (begin == std::string::npos) return "";
  const auto end = text.find_last_not_of(" \t");
  return text.substr(begin, end - begin + 1);
}

// The value as a one-entry table {v = value}.
toml::table parseValue(const std::string& assignment, const std::string& text) {
  if (text.empty()) malformed(assignment, "missing value after '=' (write \"\" for an empty string)");
  if (text.find_first_of("\n\r") != std::string::npos) malformed(assignment, "the value spans several lines");
  try {
    checkKeyDepth(text, "--set");
  } catch (const SceneError& e) {
    malformed(assignment, e.problem());
  }
  try {
    return toml::parse("v = " + text);
  } catch (const toml::parse_error& e) {
    const char first = text.front();
    const bool looksStructured = first == '[' || first == '{' || first == '"' || first == '\'';
    if (looksStructured)
      malformed(assignment, "the value is not valid TOML: " + std::string(e.description()));
    toml::table bare;
    bare.insert_or_assign("v", text);  // a bare word: a string
    return bare;
  }
}

}  // namespace

std::string applyOverride(toml::table& table, const std::string& assignment) {
  const auto equals = assignment.find('=');
  if (equals == std::string::npos) malformed(assignment, "expected key.path=value");
  const std::string path = trim(assignment.substr(0, equals));
  const auto segments = scene::parsePath(path);
  if (!segments)
    malformed(assignment, "'" + path + "' is not a key path (keys of letters, digits, '_' and '-' joined by '.', "
                                       "entries of arrays of tables as name[index])");
  if (segments->size() > kMaxKeyParts)
    malformed(assignment, "the key has " + std::to_string(segments->size()) + " parts; at most " +
                              std::to_string(kMaxKeyParts) + " (no scene key has more than four)");
  toml::table value = parseValue(assignment, trim(assignment.substr(equals + 1)));

  toml::table* current = &table;
  std::string soFar;
  for (std::size_t s = 0; s < segments->size(); ++s) {
    const auto& segment = (*segments)[s];
    const bool last = s + 1 == segments->size();
    soFar = scene::childPath(soFar, segment.key);
    if (last && !segment.index) {
      current->insert_or_assign(segment.key, std::move(*value.get("v")));
      return path;
    }
    toml::node* child = current->get(segment.key);
    if (segment.index) {
      if (!child) {
        current->insert_or_assign(segment.key, toml::array{});
        child = current->get(segment.key);
      }
      toml::array* array = child->as_array();
      if (!array) malformed(assignment, soFar + " is not an array of tables");
      const std::size_t index = *segment.index;
      if (index > array->size())
        malformed(assignment, soFar + " has " + std::to_string(array->size()) + " entries; index " +
                                  std::to_string(index) + " is neither an entry nor the next one");
      if (last) {
        if (index == array->size()) {
          array->push_back(std::move(*value.get("v")));
        } else {
          array->replace(array->begin() + static_cast<std::ptrdiff_t>(index), std::move(*value.get("v")));
        }
        return path;
      }
      if (index == array->size()) array->push_back(toml::table{});
      child = array->get(index);
      soFar = scene::indexPath(soFar, index);
    } else if (!child) {
      current->insert_or_assign(segment.key, toml::table{});
      child = current->get(segment.key);
    }
    current = child->as_table();
    if (!current) malformed(assignment, soFar + " is not a table");
  }
  return path;
}

}  // namespace mfwave
