#include "io/scene/SceneReader.hpp"

#include "core/Crc32c.hpp"
#include "io/scene/Format.hpp"
#include "io/scene/ResolvedToml.hpp"
#include "io/scene/ScenePath.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

namespace mfwave {

using scene::childPath;
using scene::formatNumber;
using scene::indexPath;
using scene::isWithin;
using scene::patternOf;

namespace {

std::vector<scene::PathSegment> segmentsOf(const std::string& path) {
  auto segments = scene::parsePath(path);
  if (!segments) throw std::logic_error("malformed scene key path '" + path + "'");
  return *segments;
}

// "a string (\"abc\")", "an integer (3)", ... for "expected X, got Y" messages.
std::string describeNode(const toml::node& node) {
  if (const auto* s = node.as_string()) return "a string (\"" + s->get() + "\")";
  if (const auto* i = node.as_integer()) return "an integer (" + std::to_string(i->get()) + ")";
  if (const auto* f = node.as_floating_point()) return "a floating-point number (" + formatNumber(f->get()) + ")";
  if (const auto* b = node.as_boolean()) return std::string("a boolean (") + (b->get() ? "true" : "false") + ")";
  if (const auto* a = node.as_array()) return a->empty() ? "an empty array" : "an array";
  if (node.is_table()) return "a table";
  return "a date or time";
}

std::string lastKey(const std::string& path) {
  const auto dot = path.rfind('.');
  return dot == std::string::npos ? path : path.substr(dot + 1);
}

}  // namespace

SceneReader::SceneReader(toml::table&& root, std::string sourceName, SceneSchema schema, std::string baseDirectory)
    : root_(std::move(root)),
      sourceName_(std::move(sourceName)),
      schema_(std::move(schema)),
      baseDirectory_(std::move(baseDirectory)) {}

void SceneReader::markOverridden(const std::string& path) { overridden_.push_back(path); }

// ---------------------------------------------------------------------------------------------
// Navigation

const toml::node* SceneReader::fetch(const std::string& path, bool reportTypeErrors) const {
  const toml::node* current = &root_;
  std::string soFar;
  for (const auto& segment : segmentsOf(path)) {
    const toml::table* table = current->as_table();
    if (!table) {
      if (reportTypeErrors) fail(soFar, "expected a table, got " + describeNode(*current));
      return nullptr;
    }
    const toml::node* child = table->get(segment.key);
    soFar = childPath(soFar, segment.key);
    if (!child) return nullptr;
    if (segment.index) {
      const toml::array* array = child->as_array();
      if (!array) {
        if (reportTypeErrors)
          fail(soFar, "expected an array of tables ([[" + soFar + "]]), got " + describeNode(*child));
        return nullptr;
      }
      child = array->get(*segment.index);
      soFar = indexPath(soFar, *segment.index);
      if (!child) return nullptr;
    }
    current = child;
  }
  return current;
}

bool SceneReader::has(const std::string& path) const { return fetch(path, false) != nullptr; }

void SceneReader::insert(const std::string& path, const std::string& literal) {
  toml::table parsed;
  try {
    parsed = toml::parse("v = " + literal);
  } catch (const toml::parse_error& e) {
    throw std::logic_error("scene default for '" + path + "' is not a TOML value: " + literal);
  }
  const auto segments = segmentsOf(path);
  toml::table* table = &root_;
  for (std::size_t s = 0; s + 1 < segments.size(); ++s) {
    const auto& segment = segments[s];
    toml::node* child = table->get(segment.key);
    if (!child) {
      if (segment.index) throw std::logic_error("scene default for '" + path + "': missing array entry");
      table->insert_or_assign(segment.key, toml::table{});
      child = table->get(segment.key);
    }
    if (segment.index) {
      toml::array* array = child->as_array();
      child = array ? array->get(*segment.index) : nullptr;
      if (!child) throw std::logic_error("scene default for '" + path + "': missing array entry");
    }
    table = child->as_table();
    if (!table) throw std::logic_error("scene default for '" + path + "': parent is not a table");
  }
  table->insert_or_assign(segments.back().key, *parsed.get("v"));
}

const toml::node* SceneReader::obtain(const std::string& path, ValueType type, const std::string& fallbackLiteral,
                                      bool mustExist) {
  const KeySpec& spec = schema_.at(patternOf(path));
  if (spec.type != type)
    throw std::logic_error("scene key '" + path + "' is registered as " + typeName(spec.type) + ", read as " +
                           typeName(type));
  const toml::node* node = fetch(path, true);
  if (!node) {
    const std::string& literal = fallbackLiteral.empty() ? spec.defaultLiteral : fallbackLiteral;
    if (literal.empty()) {
      if (mustExist) fail(path, "missing required key (" + spec.doc + ")");
      return nullptr;
    }
    insert(path, literal);
    node = fetch(path, true);
  }
  read_.insert(path);
  return node;
}

// ---------------------------------------------------------------------------------------------
// Values

void SceneReader::checkNumber(Real x, const std::string& path, const KeySpec& spec) const {
  if (std::isnan(x)) fail(path, "must be a finite number, got nan");
  if (std::isinf(x) && !spec.infinityAllowed) fail(path, "must be a finite number, got " + formatNumber(x));
  if (!spec.range.contains(x)) fail(path, spec.range.violation(x));
}

std::string SceneReader::checkedString(const toml::node& node, const std::string& path, const KeySpec& spec) const {
  const auto* s = node.as_string();
  if (!s) fail(path, "expected a string, got " + describeNode(node));
  const std::string& value = s->get();
  if (spec.choices.empty() || std::find(spec.choices.begin(), spec.choices.end(), value) != spec.choices.end())
    return value;
  if (std::find(spec.unsupported.begin(), spec.unsupported.end(), value) != spec.unsupported.end())
    fail(path, "'" + value + "' is not supported yet; supported: " + scene::joinNames(spec.choices));
  std::string problem = "'" + value + "' is not valid; must be one of: " + scene::joinNames(spec.choices);
  if (const auto suggestion = scene::closestMatch(value, spec.choices))
    problem += "; did you mean '" + *suggestion + "'?";
  fail(path, problem);
}

std::optional<Real> SceneReader::readNumber(const std::string& path, const std::string& fallback, bool mustExist) {
  const toml::node* node = obtain(path, ValueType::Number, fallback, mustExist);
  if (!node) return std::nullopt;
  if (!node->is_number()) fail(path, "expected a number, got " + describeNode(*node));
  const Real x = *node->value<Real>();
  checkNumber(x, path, schema_.at(patternOf(path)));
  return x;
}

std::optional<std::int64_t> SceneReader::readInteger(const std::string& path, const std::string& fallback,
                                                     bool mustExist) {
  const toml::node* node = obtain(path, ValueType::Integer, fallback, mustExist);
  if (!node) return std::nullopt;
  if (!node->is_integer()) fail(path, "expected an integer, got " + describeNode(*node));
  const std::int64_t i = node->as_integer()->get();
  const KeySpec& spec = schema_.at(patternOf(path));
  if (!spec.range.contains(static_cast<Real>(i))) fail(path, spec.range.violation(static_cast<Real>(i)));
  return i;
}

std::optional<bool> SceneReader::readBoolean(const std::string& path, const std::string& fallback, bool mustExist) {
  const toml::node* node = obtain(path, ValueType::Boolean, fallback, mustExist);
  if (!node) return std::nullopt;
  if (!node->is_boolean()) fail(path, "expected a boolean (true or false), got " + describeNode(*node));
  return node->as_boolean()->get();
}

std::optional<std::string> SceneReader::readString(const std::string& path, const std::string& fallback,
                                                   bool mustExist) {
  const toml::node* node = obtain(path, ValueType::String, fallback, mustExist);
  if (!node) return std::nullopt;
  return checkedString(*node, path, schema_.at(patternOf(path)));
}

const toml::array* SceneReader::readArray(const std::string& path, ValueType type, std::size_t length,
                                          const std::string& fallback, bool mustExist) {
  const toml::node* node = obtain(path, type, fallback, mustExist);
  if (!node) return nullptr;
  const toml::array* array = node->as_array();
  if (!array) fail(path, "expected a " + typeName(type) +
                             ", got " + describeNode(*node));
  if (length > 0 && array->size() != length)
    fail(path, "must have " + std::to_string(length) + (length == 1 ? " entry" : " entries") +
                   " (one per axis), got " + std::to_string(array->size()));
  return array;
}

std::optional<std::vector<Real>> SceneReader::readNumbers(const std::string& path, std::size_t length,
                                                          const std::string& fallback, bool mustExist) {
  const toml::array* array = readArray(path, ValueType::NumberArray, length, fallback, mustExist);
  if (!array) return std::nullopt;
  const KeySpec& spec = schema_.at(patternOf(path));
  std::vector<Real> values;
  for (std::size_t i = 0; i < array->size(); ++i) {
    const toml::node& element = *array->get(i);
    if (!element.is_number()) fail(indexPath(path, i), "expected a number, got " + describeNode(element));
    values.push_back(*element.value<Real>());
    checkNumber(values.back(), indexPath(path, i), spec);
  }
  return values;
}

std::optional<std::vector<std::string>> SceneReader::readStrings(const std::string& path, const std::string& fallback,
                                                                 bool mustExist) {
  const toml::array* array = readArray(path, ValueType::StringArray, 0, fallback, mustExist);
  if (!array) return std::nullopt;
  const KeySpec& spec = schema_.at(patternOf(path));
  std::vector<std::string> values;
  for (std::size_t i = 0; i < array->size(); ++i) values.push_back(checkedString(*array->get(i), indexPath(path, i), spec));
  return values;
}

std::optional<std::vector<bool>> SceneReader::readBooleans(const std::string& path, std::size_t length,
                                                           const std::string& fallback, bool mustExist) {
  const toml::array* array = readArray(path, ValueType::BooleanArray, length, fallback, mustExist);
  if (!array) return std::nullopt;
  std::vector<bool> values;
  for (std::size_t i = 0; i < array->size(); ++i) {
    const toml::node& element = *array->get(i);
    if (!element.is_boolean()) fail(indexPath(path, i), "expected a boolean, got " + describeNode(element));
    values.push_back(element.as_boolean()->get());
  }
  return values;
}

Real SceneReader::number(const std::string& path) { return *readNumber(path, "", true); }
Real SceneReader::number(const std::string& path, Real fallback) {
  return *readNumber(path, scene::tomlNumber(fallback), true);
}
std::optional<Real> SceneReader::optionalNumber(const std::string& path) { return readNumber(path, "", false); }

std::int64_t SceneReader::integer(const std::string& path) { return *readInteger(path, "", true); }
std::int64_t SceneReader::integer(const std::string& path, std::int64_t fallback) {
  return *readInteger(path, std::to_string(fallback), true);
}
std::optional<std::int64_t> SceneReader::optionalInteger(const std::string& path) {
  return readInteger(path, "", false);
}

bool SceneReader::boolean(const std::string& path) { return *readBoolean(path, "", true); }
bool SceneReader::boolean(const std::string& path, bool fallback) {
  return *readBoolean(path, fallback ? "true" : "false", true);
}

std::string SceneReader::string(const std::string& path) { return *readString(path, "", true); }
std::string SceneReader::string(const std::string& path, const std::string& fallback) {
  return *readString(path, scene::tomlString(fallback), true);
}
std::optional<std::string> SceneReader::optionalString(const std::string& path) {
  return readString(path, "", false);
}

std::vector<Real> SceneReader::numbers(const std::string& path, std::size_t length) {
  return *readNumbers(path, length, "", true);
}
std::vector<Real> SceneReader::numbers(const std::string& path, std::size_t length, const std::vector<Real>& fallback) {
  return *readNumbers(path, length, scene::tomlArray(fallback), true);
}
std::optional<std::vector<Real>> SceneReader::optionalNumbers(const std::string& path, std::size_t length) {
  return readNumbers(path, length, "", false);
}
std::vector<int> SceneReader::wholeNumbers(const std::string& path) {
  std::vector<int> out;
  for (Real value : numbers(path)) {
    if (value != std::round(value)) fail(path, "must be whole numbers, got " + scene::formatNumber(value));
    out.push_back(static_cast<int>(value));
  }
  return out;
}

std::vector<std::string> SceneReader::strings(const std::string& path) { return *readStrings(path, "", true); }
std::vector<std::string> SceneReader::strings(const std::string& path, const std::vector<std::string>& fallback) {
  return *readStrings(path, scene::tomlArray(fallback), true);
}

std::vector<bool> SceneReader::booleans(const std::string& path, std::size_t length) {
  return *readBooleans(path, length, "", true);
}
std::vector<bool> SceneReader::booleans(const std::string& path, std::size_t length, const std::vector<bool>& fallback) {
  return *readBooleans(path, length, scene::tomlArray(fallback), true);
}

// ---------------------------------------------------------------------------------------------
// Tables

std::size_t SceneReader::count(const std::string& path) {
  const KeySpec& spec = schema_.at(patternOf(path));
  if (spec.type != ValueType::TableArray)
    throw std::logic_error("scene key '" + path + "' is not registered as an array of tables");
  const toml::node* node = fetch(path, true);
  if (!node) return 0;
  const std::string name = lastKey(path);
  const toml::array* array = node->as_array();
  if (!array) fail(path, "expected an array of tables ([[" + name + "]]), got " + describeNode(*node));
  for (std::size_t i = 0; i < array->size(); ++i)
    if (!array->get(i)->is_table())
      fail(indexPath(path, i), "expected a table (an entry of [[" + name + "]]), got " + describeNode(*array->get(i)));
  return array->size();
}

bool SceneReader::table(const std::string& path, bool required, const std::string& fallbackLiteral) {
  const KeySpec& spec = schema_.at(patternOf(path));
  if (spec.type != ValueType::Table) throw std::logic_error("scene key '" + path + "' is not registered as a table");
  const toml::node* node = fetch(path, true);
  if (node) {
    if (!node->is_table()) fail(path, "expected a table, got " + describeNode(*node));
    return true;
  }
  if (!fallbackLiteral.empty()) {
    insert(path, fallbackLiteral);
    return true;
  }
  if (required) fail(path, "missing required key (" + spec.doc + ")");
  return false;
}

void SceneReader::resolveString(const std::string& path, const std::string& value) {
  if (!read_.count(path)) throw std::logic_error("resolveString: '" + path + "' was not read");
  insert(path, scene::tomlString(value));
}

SceneTable SceneReader::section(const std::string& prefix) { return SceneTable(*this, prefix); }

// ---------------------------------------------------------------------------------------------
// Errors

std::string SceneReader::locate(const std::string& path) const {
  for (const auto& overridden : overridden_)
    if (isWithin(path, overridden)) return "--set";
  std::size_t line = root_.source().begin.line;
  const toml::node* current = &root_;
  const auto segments = scene::parsePath(path);
  if (segments) {
    for (const auto& segment : *segments) {
      const toml::table* table = current->as_table();
      const toml::node* child = table ? table->get(segment.key) : nullptr;
      if (child && segment.index) {
        const toml::array* array = child->as_array();
        child = array ? array->get(*segment.index) : nullptr;
      }
      if (!child) break;
      current = child;
      if (child->source().begin.line > 0) line = child->source().begin.line;
    }
  }
  return sourceName_ + ":" + std::to_string(std::max<std::size_t>(line, 1));
}

SceneError SceneReader::error(const std::string& path, const std::string& problem) const {
  return SceneError(locate(path), path, problem);
}

void SceneReader::fail(const std::string& path, const std::string& problem) const { throw error(path, problem); }

// ---------------------------------------------------------------------------------------------
// After reading

bool SceneReader::anyReadWithin(const std::string& path) const {
  for (const auto& read : read_)
    if (isWithin(read, path)) return true;
  return false;
}

void SceneReader::collectUnread(const toml::table& table, const std::string& prefix, Unread& found) const {
  for (const auto& [key, node] : table) {
    const std::string name(key.str());
    const std::string path = childPath(prefix, name);
    if (read_.count(path)) continue;
    const std::string pattern = patternOf(path);
    const KeySpec* spec = schema_.find(pattern);
    const bool isTableArray = spec && spec->type == ValueType::TableArray;
    if (node.is_table() && !isTableArray && schema_.isTable(pattern)) {
      if (spec && !spec->condition.empty() && !anyReadWithin(path))
        found.emplace_back(&node, error(path, "not used here (only allowed when " + spec->condition + ")"));
      else
        collectUnread(*node.as_table(), path, found);
      continue;
    }
    if (isTableArray && node.is_array()) {
      const toml::array& array = *node.as_array();
      bool allTables = true;
      for (const auto& element : array) allTables = allTables && element.is_table();
      if (allTables) {
        for (std::size_t i = 0; i < array.size(); ++i) collectUnread(*array.get(i)->as_table(), indexPath(path, i), found);
        continue;
      }
    }
    std::string problem;
    if (spec || schema_.isTable(pattern)) {
      problem = spec && !spec->condition.empty() ? "not used here (only allowed when " + spec->condition + ")"
                                                 : "is a valid key, but nothing reads it with these settings";
    } else {
      problem = "unknown key";
      const auto candidates = schema_.childNames(patternOf(prefix));
      if (const auto suggestion = scene::closestMatch(name, candidates))
        problem += "; did you mean '" + *suggestion + "'?";
      else if (!candidates.empty())
        problem += "; valid keys here: " + scene::joinNames(candidates);
    }
    found.emplace_back(&node, error(path, problem));
  }
}

void SceneReader::checkAllKeysRead() const {
  Unread found;
  collectUnread(root_, "", found);
  if (found.empty()) return;
  // The first in the file; overridden keys ("--set") first of all.
  auto lineOf = [](const std::pair<const toml::node*, SceneError>& entry) {
    return entry.second.location() == "--set" ? 0 : entry.first->source().begin.line;
  };
  const auto first = std::min_element(found.begin(), found.end(), [&](const auto& a, const auto& b) {
    return lineOf(a) < lineOf(b);
  });
  throw first->second;
}

std::string SceneReader::resolvedToml() const { return scene::writeResolvedToml(root_, schema_, sourceName_); }

std::string SceneReader::digest(const std::vector<std::string>& excluded) const {
  const std::string text = canonicalToml(excluded);
  char hex[32];
  std::snprintf(hex, sizeof hex, "%08x", static_cast<unsigned>(crc32c(text.data(), text.size())));
  return std::string("crc32c ") + hex + ", " + std::to_string(text.size()) + " bytes";
}

std::string SceneReader::canonicalToml(const std::vector<std::string>& excluded) const {
  toml::table root = root_;
  for (const std::string& path : excluded) {
    const auto dot = path.rfind('.');
    toml::table* parent = dot == std::string::npos ? &root : root.at_path(path.substr(0, dot)).as_table();
    if (parent) parent->erase(dot == std::string::npos ? path : path.substr(dot + 1));
  }
  return scene::writeResolvedToml(root, schema_, "");
}

}  // namespace mfwave
