#include "io/scene/SceneSchema.hpp"

#include "io/scene/Format.hpp"
#include "io/scene/ScenePath.hpp"

#include <algorithm>
#include <stdexcept>

namespace mfwave {

using scene::formatNumber;

std::string typeName(ValueType type) {
  switch (type) {
    case ValueType::Number: return "number";
    case ValueType::Integer: return "integer";
    case ValueType::Boolean: return "boolean";
    case ValueType::String: return "string";
    case ValueType::NumberArray: return "number array";
    case ValueType::StringArray: return "string array";
    case ValueType::BooleanArray: return "boolean array";
    case ValueType::Table: return "table";
    case ValueType::TableArray: return "array of tables";
  }
  return "?";
}

bool ValueRange::contains(Real x) const {
  if (min && !(minInclusive ? x >= *min : x > *min)) return false;
  if (max && !(maxInclusive ? x <= *max : x < *max)) return false;
  return true;
}

std::string ValueRange::describe() const {
  if (min && max)
    return std::string(minInclusive ? "[" : "(") + formatNumber(*min) + ", " + formatNumber(*max) +
           (maxInclusive ? "]" : ")");
  if (min) return std::string(minInclusive ? ">= " : "> ") + formatNumber(*min);
  if (max) return std::string(maxInclusive ? "<= " : "< ") + formatNumber(*max);
  return "";
}

std::string ValueRange::violation(Real x) const {
  const std::string got = ", got " + formatNumber(x);
  if (min && max) return "must lie in " + describe() + got;
  if (min && *min == 0) return (minInclusive ? "must be non-negative" : "must be positive") + got;
  if (min) return (minInclusive ? "must be at least " : "must be greater than ") + formatNumber(*min) + got;
  if (max) return (maxInclusive ? "must be at most " : "must be less than ") + formatNumber(*max) + got;
  return "is out of range" + got;
}

std::string KeySpec::defaultText() const {
  if (!defaultNote.empty()) return defaultNote;
  if (!defaultLiteral.empty()) return defaultLiteral;
  return isRequired ? "required" : "-";
}

KeySpec& SceneSchema::add(const std::string& pattern, ValueType type) {
  // A pattern is a path whose indices are all "[]": check it by parsing it with "[0]".
  std::string asPath;
  for (std::size_t i = 0; i < pattern.size(); ++i) {
    if (pattern.compare(i, 2, "[]") == 0) {
      asPath += "[0]";
      ++i;
    } else {
      asPath += pattern[i];
    }
  }
  if (!scene::parsePath(asPath) || scene::patternOf(asPath) != pattern)
    throw std::logic_error("SceneSchema::add: malformed key pattern '" + pattern + "'");
  if (find(pattern)) throw std::logic_error("SceneSchema::add: key '" + pattern + "' registered twice");
  KeySpec spec;
  spec.path = pattern;
  spec.type = type;
  keys_.push_back(std::move(spec));
  return keys_.back();
}

void SceneSchema::addChoice(const std::string& pattern, const std::string& value) {
  KeySpec& spec = at(pattern);
  if (std::find(spec.choices.begin(), spec.choices.end(), value) == spec.choices.end()) spec.choices.push_back(value);
}

const KeySpec* SceneSchema::find(const std::string& pattern) const {
  for (const auto& spec : keys_)
    if (spec.path == pattern) return &spec;
  return nullptr;
}

const KeySpec& SceneSchema::at(const std::string& pattern) const {
  const KeySpec* spec = find(pattern);
  if (!spec) throw std::logic_error("scene key '" + pattern + "' is not registered in the scene schema");
  return *spec;
}

KeySpec& SceneSchema::at(const std::string& pattern) {
  return const_cast<KeySpec&>(static_cast<const SceneSchema&>(*this).at(pattern));
}

std::vector<std::string> SceneSchema::childNames(const std::string& parentPattern) const {
  std::vector<std::string> names;
  const std::string prefix = parentPattern.empty() ? "" : parentPattern + ".";
  for (const auto& spec : keys_) {
    if (spec.path.compare(0, prefix.size(), prefix) != 0) continue;
    std::string rest = spec.path.substr(prefix.size());
    rest = rest.substr(0, rest.find('.'));
    if (rest.size() >= 2 && rest.compare(rest.size() - 2, 2, "[]") == 0) rest.resize(rest.size() - 2);
    if (!rest.empty() && std::find(names.begin(), names.end(), rest) == names.end()) names.push_back(rest);
  }
  return names;
}

bool SceneSchema::isTable(const std::string& pattern) const {
  for (const auto& spec : keys_) {
    if (spec.path == pattern) return spec.type == ValueType::Table || spec.type == ValueType::TableArray;
    if (scene::isWithin(spec.path, pattern) && spec.path.size() > pattern.size()) return true;
  }
  return false;
}

std::size_t SceneSchema::order(const std::string& pattern) const {
  for (std::size_t i = 0; i < keys_.size(); ++i)
    if (keys_[i].path == pattern) return i;
  // A table that is only the parent of registered keys sorts with its first child.
  for (std::size_t i = 0; i < keys_.size(); ++i)
    if (scene::isWithin(keys_[i].path, pattern)) return i;
  return keys_.size();
}

std::string SceneSchema::describe() const {
  struct Row {
    std::string path, type, unit, value, range, doc;
  };
  std::vector<Row> rows;
  for (const auto& spec : keys_) {
    std::string range = spec.range.describe();
    if (!spec.choices.empty()) range = scene::joinNames(spec.choices, "|");
    std::string doc = spec.doc;
    if (!spec.condition.empty()) doc += " (only when " + spec.condition + ")";
    if (!spec.unsupported.empty()) doc += " (not supported yet: " + scene::joinNames(spec.unsupported) + ")";
    rows.push_back({spec.path, typeName(spec.type), spec.unit.empty() ? "" : spec.unit, spec.defaultText(), range, doc});
  }
  std::size_t w[5] = {4, 4, 4, 7, 5};
  for (const auto& r : rows) {
    w[0] = std::max(w[0], r.path.size());
    w[1] = std::max(w[1], r.type.size());
    w[2] = std::max(w[2], r.unit.size());
    w[3] = std::max(w[3], std::min<std::size_t>(r.value.size(), 24));
    w[4] = std::max(w[4], std::min<std::size_t>(r.range.size(), 28));
  }
  auto pad = [](const std::string& s, std::size_t width) {
    return s.size() >= width ? s + "  " : s + std::string(width - s.size() + 2, ' ');
  };
  std::string out = pad("key", w[0]) + pad("type", w[1]) + pad("unit", w[2]) + pad("default", w[3]) +
                    pad("range", w[4]) + "meaning\n";
  std::string section;
  for (const auto& r : rows) {
    const std::string top = r.path.substr(0, r.path.find_first_of(".["));
    if (top != section && !section.empty()) out += "\n";
    section = top;
    out += pad(r.path, w[0]) + pad(r.type, w[1]) + pad(r.unit, w[2]) + pad(r.value, w[3]) + pad(r.range, w[4]) +
           r.doc + "\n";
  }
  return out;
}

}  // namespace mfwave
