#pragma once
// The catalogue of scene keys: for each key path pattern its type, unit, default (or
// "required"), allowed range or values, and a one-line description. The reader takes types,
// defaults and ranges from here, so they are written down once; `--help` prints describe();
// docs/scenes.md lists every pattern (a test checks it).
//
// Patterns name arrays of tables with "[]": "boundary[].type", "load[].time_function.delay".
// The common sections are registered by SceneSchema::common() (CommonKeys.cpp); a driver adds
// its own keys ("study.cases") and a method its options ("method.order") with add(), and
// extends the valid method names with addChoice("method.name", ...).

#include "core/Types.hpp"

#include <deque>
#include <optional>
#include <string>
#include <vector>

namespace mfwave {

enum class ValueType { Number, Integer, Boolean, String, NumberArray, StringArray, BooleanArray, Table, TableArray };

// "number", "integer", "boolean", "string", "number array", "string array", "boolean array",
// "table", "array of tables".
std::string typeName(ValueType type);

// Allowed interval of a number or integer (of each entry of a number array).
struct ValueRange {
  std::optional<Real> min, max;
  bool minInclusive = true, maxInclusive = true;

  bool empty() const { return !min && !max; }
  bool contains(Real x) const;
  // For docs: "> 0", ">= 1", "[0, 0.5]", "(-1, 0.5)"; "" when unrestricted.
  std::string describe() const;
  // For errors: "must be positive, got -0.5", "must lie in [1, 3], got 4".
  std::string violation(Real x) const;
};

struct KeySpec {
  std::string path;  // pattern, e.g. "boundary[].type"
  ValueType type = ValueType::Number;
  std::string unit;  // "m", "s", "Pa", "kg/m^3", "1/s", "-" (dimensionless); "" for non-numbers
  bool isRequired = false;
  std::string defaultLiteral;  // TOML literal inserted when the key is absent ("0.5", "\"velocity\"")
  std::string defaultNote;     // a default that depends on other keys, in words ("1.5 / peak_frequency")
  ValueRange range;
  bool infinityAllowed = false;         // numbers: accept inf (nan is always rejected)
  std::vector<std::string> choices;     // strings (and string arrays): the allowed values
  std::vector<std::string> unsupported; // recognised names that are rejected as "not supported yet"
  std::string condition;                // when the key is allowed at all ("type = traction")
  std::string doc;                      // one line

  // Builders, to register a key in one statement.
  KeySpec& withUnit(std::string u) { unit = std::move(u); return *this; }
  KeySpec& required() { isRequired = true; return *this; }
  KeySpec& defaultsTo(std::string literal) { defaultLiteral = std::move(literal); return *this; }
  KeySpec& defaultsToNote(std::string note) { defaultNote = std::move(note); return *this; }
  KeySpec& positive() { range.min = 0; range.minInclusive = false; return *this; }
  KeySpec& nonNegative() { range.min = 0; range.minInclusive = true; return *this; }
  KeySpec& atLeast(Real x) { range.min = x; range.minInclusive = true; return *this; }
  KeySpec& above(Real x) { range.min = x; range.minInclusive = false; return *this; }
  KeySpec& between(Real lo, Real hi, bool loInclusive = true, bool hiInclusive = true) {
    range.min = lo; range.max = hi; range.minInclusive = loInclusive; range.maxInclusive = hiInclusive;
    return *this;
  }
  KeySpec& allowInfinity() { infinityAllowed = true; return *this; }
  KeySpec& oneOf(std::vector<std::string> values) { choices = std::move(values); return *this; }
  KeySpec& notSupportedYet(std::vector<std::string> names) { unsupported = std::move(names); return *this; }
  KeySpec& when(std::string c) { condition = std::move(c); return *this; }
  KeySpec& describedAs(std::string text) { doc = std::move(text); return *this; }

  // The default column of describe(): "required", the literal, the note, or "-".
  std::string defaultText() const;
};

class SceneSchema {
 public:
  // The common sections: scene, geometry, material, method, boundary, load, integrator, probe,
  // output, stability (and the time-function keys under boundary[] and load[]).
  static SceneSchema common();

  // Registers a key; the reference stays valid until the schema is destroyed. Throws
  // std::logic_error for a malformed or duplicate pattern.
  KeySpec& add(const std::string& pattern, ValueType type);
  // The time-function keys under `prefix` ("load[].time_function"): type and the parameters of
  // each kind; `defaultNote` is the default column of the table itself.
  void addTimeFunction(const std::string& prefix, const std::string& defaultNote, const std::string& doc);
  // Adds a valid value to a string key ("method.name").
  void addChoice(const std::string& pattern, const std::string& value);

  const KeySpec* find(const std::string& pattern) const;
  // Throws std::logic_error when the pattern is not registered.
  const KeySpec& at(const std::string& pattern) const;
  KeySpec& at(const std::string& pattern);
  // Key names valid directly under `parentPattern` ("" for the top level, "boundary[]" for an
  // entry of [[boundary]]), in registration order.
  std::vector<std::string> childNames(const std::string& parentPattern) const;
  // True when `pattern` is a registered table / array of tables, or the parent of a registered key.
  bool isTable(const std::string& pattern) const;
  // Position of a pattern in registration order (for ordering the resolved scene); keys.size()
  // for an unknown pattern.
  std::size_t order(const std::string& pattern) const;

  const std::deque<KeySpec>& keys() const { return keys_; }
  // The catalogue as a readable list, one key per line: path, type, unit, default, range or
  // allowed values, description.
  std::string describe() const;

 private:
  std::deque<KeySpec> keys_;
};

}  // namespace mfwave
