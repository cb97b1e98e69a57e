#pragma once
// Reads a parsed scene through the schema: types, defaults and ranges come from the schema;
// every read is recorded; defaults are inserted into the table as they are used, so that after
// reading, resolvedToml() is the fully resolved scene. Errors are SceneErrors naming the full
// key path and the file and line of the offending node ("--set" for overridden nodes; for a
// missing key, the line of its parent table).
//
// Components read their own keys (a method reads its [method] options after the common
// sections), so the check for unknown keys is a separate call: checkAllKeysRead(), made by the
// driver after every component has read its options and before any work.
//
//   SceneReader reader = loadScene(path, overrides, schema);   // see LoadScene.hpp
//   Scene scene = readScene(reader);                           // common sections (Scene.hpp)
//   auto order = reader.integer("method.order");               // a method's own option
//   reader.checkAllKeysRead();
//   write(out / "scene.resolved.toml", reader.resolvedToml());

#include "core/Types.hpp"
#include "io/scene/SceneError.hpp"
#include "io/scene/SceneSchema.hpp"

#include <toml++/toml.h>

#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace mfwave {

class SceneTable;

class SceneReader {
 public:
  // `sourceName` is the file name used in messages; relative file paths in the scene
  // (tabulated time functions) are resolved against `baseDirectory`.
  SceneReader(toml::table&& root, std::string sourceName, SceneSchema schema = SceneSchema::common(),
              std::string baseDirectory = ".");

  // The schema, for drivers and methods to register their keys before reading them.
  SceneSchema& schema() { return schema_; }
  const SceneSchema& schema() const { return schema_; }
  const std::string& sourceName() const { return sourceName_; }
  const std::string& baseDirectory() const { return baseDirectory_; }
  // Records that the value at `path` (and below) came from a --set override.
  void markOverridden(const std::string& path);

  // --- reading. Every path must be registered in the schema (std::logic_error otherwise).
  // Plain form: the value, or the schema's default (inserted), or a "missing required key" error.
  // With a fallback: a default computed by the caller, inserted when the key is absent.
  // optional...: the value or the schema default, or nullopt when absent without a default.
  // Array readers check the length when `length` > 0.
  Real number(const std::string& path);
  Real number(const std::string& path, Real fallback);
  std::optional<Real> optionalNumber(const std::string& path);
  std::int64_t integer(const std::string& path);
  std::int64_t integer(const std::string& path, std::int64_t fallback);
  std::optional<std::int64_t> optionalInteger(const std::string& path);
  bool boolean(const std::string& path);
  bool boolean(const std::string& path, bool fallback);
  std::string string(const std::string& path);
  std::string string(const std::string& path, const std::string& fallback);
  std::optional<std::string> optionalString(const std::string& path);
  std::vector<Real> numbers(const std::string& path, std::size_t length = 0);
  std::vector<Real> numbers(const std::string& path, std::size_t length, const std::vector<Real>& fallback);
  std::optional<std::vector<Real>> optionalNumbers(const std::string& path, std::size_t length = 0);
  // A number array whose entries must be whole (a list of dimensions, of orders): fails naming the
  // key at the first entry with a fraction.
  std::vector<int> wholeNumbers(const std::string& path);
  std::vector<std::string> strings(const std::string& path);
  std::vector<std::string> strings(const std::string& path, const std::vector<std::string>& fallback);
  std::vector<bool> booleans(const std::string& path, std::size_t length = 0);
  std::vector<bool> booleans(const std::string& path, std::size_t length, const std::vector<bool>& fallback);

  // Number of entries of an array of tables ([[boundary]]); 0 when absent.
  std::size_t count(const std::string& path);
  // A (sub-)table: true when present; when absent, inserts `fallbackLiteral` (a TOML inline
  // table, "{ type = \"constant\", value = 1.0 }") if given and returns true, or fails with
  // "missing required key" if `required`, or returns false.
  bool table(const std::string& path, bool required = false, const std::string& fallbackLiteral = "");
  // Whether a key is present (does not count as reading it).
  bool has(const std::string& path) const;
  // Replaces a string that was read by its resolved form in the resolved scene (a relative
  // file path made absolute).
  void resolveString(const std::string& path, const std::string& value);
  // A view of the reader under `prefix` ("method", "load[0]").
  SceneTable section(const std::string& prefix);

  // --- errors
  // "scene.toml:12" / "--set": where the node at `path` (or its nearest present parent) is.
  std::string locate(const std::string& path) const;
  SceneError error(const std::string& path, const std::string& problem) const;
  [[noreturn]] void fail(const std::string& path, const std::string& problem) const;

  // --- after reading
  // Throws SceneError for the first (by line) key that no component read: an unknown key with
  // the closest valid key at its level suggested, or a valid key that these settings do not use
  // ("only allowed when type = traction").
  void checkAllKeysRead() const;
  // The scene with every default inserted, as TOML (keys in schema order).
  std::string resolvedToml() const;
  // Identifies the resolved scene for checkpoints: a CRC-32C and the length of its resolved TOML
  // with the keys `excluded` ("output.folder", ...) left out, so that settings which do not change
  // the computation (where it is written, how often it is checkpointed) do not make another scene.
  std::string digest(const std::vector<std::string>& excluded) const;
  // The resolved TOML the digest is taken of: no source name in its header, `excluded` left out.
  std::string canonicalToml(const std::vector<std::string>& excluded) const;
  const toml::table& root() const { return root_; }

 private:
  using Unread = std::vector<std::pair<const toml::node*, SceneError>>;
  const toml::node* fetch(const std::string& path, bool reportTypeErrors) const;
  const toml::node* obtain(const std::string& path, ValueType type, const std::string& fallbackLiteral,
                           bool mustExist);
  void insert(const std::string& path, const std::string& literal);
  std::optional<Real> readNumber(const std::string& path, const std::string& fallback, bool mustExist);
  std::optional<std::int64_t> readInteger(const std::string& path, const std::string& fallback, bool mustExist);
  std::optional<bool> readBoolean(const std::string& path, const std::string& fallback, bool mustExist);
  std::optional<std::string> readString(const std::string& path, const std::string& fallback, bool mustExist);
  const toml::array* readArray(const std::string& path, ValueType type, std::size_t length,
                               const std::string& fallback, bool mustExist);
  std::optional<std::vector<Real>> readNumbers(const std::string& path, std::size_t length,
                                               const std::string& fallback, bool mustExist);
  std::optional<std::vector<std::string>> readStrings(const std::string& path, const std::string& fallback,
                                                      bool mustExist);
  std::optional<std::vector<bool>> readBooleans(const std::string& path, std::size_t length,
                                                const std::string& fallback, bool mustExist);
  std::string checkedString(const toml::node& node, const std::string& path, const KeySpec& spec) const;
  void checkNumber(Real x, const std::string& path, const KeySpec& spec) const;
  bool anyReadWithin(const std::string& path) const;
  void collectUnread(const toml::table& table, const std::string& path, Unread& found) const;

  toml::table root_;
  std::string sourceName_;
  SceneSchema schema_;
  std::string baseDirectory_;
  std::set<std::string> read_;
  std::vector<std::string> overridden_;
};

// The reader seen from a table: keys are relative to the prefix.
class SceneTable {
 public:
  SceneTable(SceneReader& reader, std::string prefix) : reader_(&reader), prefix_(std::move(prefix)) {}
  const std::string& prefix() const { return prefix_; }
  std::string path(const std::string& key) const { return prefix_.empty() ? key : prefix_ + "." + key; }
  SceneReader& reader() const { return *reader_; }

  Real number(const std::string& key) const { return reader_->number(path(key)); }
  Real number(const std::string& key, Real fallback) const { return reader_->number(path(key), fallback); }
  std::optional<Real> optionalNumber(const std::string& key) const { return reader_->optionalNumber(path(key)); }
  std::int64_t integer(const std::string& key) const { return reader_->integer(path(key)); }
  std::int64_t integer(const std::string& key, std::int64_t fallback) const {
    return reader_->integer(path(key), fallback);
  }
  bool boolean(const std::string& key) const { return reader_->boolean(path(key)); }
  bool boolean(const std::string& key, bool fallback) const { return reader_->boolean(path(key), fallback); }
  std::string string(const std::string& key) const { return reader_->string(path(key)); }
  std::vector<Real> numbers(const std::string& key, std::size_t length = 0) const {
    return reader_->numbers(path(key), length);
  }
  std::vector<std::string> strings(const std::string& key) const { return reader_->strings(path(key)); }
  bool has(const std::string& key) const { return reader_->has(path(key)); }
  [[noreturn]] void fail(const std::string& key, const std::string& problem) const {
    reader_->fail(path(key), problem);
  }

 private:
  SceneReader* reader_;
  std::string prefix_;
};

}  // namespace mfwave
