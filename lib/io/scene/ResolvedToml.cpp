#include "io/scene/ResolvedToml.hpp"

#include "io/scene/Format.hpp"
#include "io/scene/ScenePath.hpp"

#include <algorithm>
#include <cctype>
#include <sstream>

namespace mfwave::scene {
namespace {

std::string keyText(const std::string& key) {
  const bool bare = !key.empty() && std::all_of(key.begin(), key.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '-';
  });
  return bare ? key : tomlString(key);
}

bool isSubTable(const toml::node& node) { return node.is_table() && !node.as_table()->is_inline(); }

bool isTableArray(const toml::node& node) {
  const toml::array* array = node.as_array();
  if (!array || array->empty()) return false;
  return std::all_of(array->begin(), array->end(), [](const toml::node& e) { return isSubTable(e); });
}

class Writer {
 public:
  explicit Writer(const SceneSchema& schema) : schema_(schema) {}

  // Keys of `table` in schema order, unknown keys last in name order.
  std::vector<std::string> orderedKeys(const toml::table& table, const std::string& pattern) const {
    std::vector<std::string> keys;
    for (const auto& entry : table) keys.emplace_back(entry.first.str());
    std::stable_sort(keys.begin(), keys.end(), [&](const std::string& a, const std::string& b) {
      return schema_.order(childPath(pattern, a)) < schema_.order(childPath(pattern, b));
    });
    return keys;
  }

  std::string value(const toml::node& node, const std::string& pattern) const {
    if (const auto* s = node.as_string()) return tomlString(s->get());
    if (const auto* i = node.as_integer()) return std::to_string(i->get());
    if (const auto* f = node.as_floating_point()) return tomlNumber(f->get());
    if (const auto* b = node.as_boolean()) return b->get() ? "true" : "false";
    if (const auto* a = node.as_array()) {
      std::string out = "[";
      for (std::size_t k = 0; k < a->size(); ++k) out += (k ? ", " : "") + value(*a->get(k), pattern + "[]");
      return out + "]";
    }
    if (const auto* t = node.as_table()) {
      std::string out = "{";
      const auto keys = orderedKeys(*t, pattern);
      for (std::size_t k = 0; k < keys.size(); ++k)
        out += (k ? ", " : " ") + keyText(keys[k]) + " = " + value(*t->get(keys[k]), childPath(pattern, keys[k]));
      return out + (keys.empty() ? "}" : " }");
    }
    std::ostringstream out;  // dates and times
    if (const auto* d = node.as_date()) out << d->get();
    if (const auto* t = node.as_time()) out << t->get();
    if (const auto* dt = node.as_date_time()) out << dt->get();
    return out.str();
  }

  void body(std::ostringstream& out, const toml::table& table, const std::string& pattern,
            const std::string& header) const {
    const auto keys = orderedKeys(table, pattern);
    for (const auto& key : keys) {
      const toml::node& node = *table.get(key);
      if (isSubTable(node) || isTableArray(node)) continue;
      out << keyText(key) << " = " << value(node, childPath(pattern, key)) << "\n";
    }
    for (const auto& key : keys) {
      const toml::node& node = *table.get(key);
      const std::string childHeader = header.empty() ? keyText(key) : header + "." + keyText(key);
      if (isSubTable(node)) {
        out << "\n[" << childHeader << "]\n";
        body(out, *node.as_table(), childPath(pattern, key), childHeader);
      } else if (isTableArray(node)) {
        for (const auto& element : *node.as_array()) {
          out << "\n[[" << childHeader << "]]\n";
          body(out, *element.as_table(), childPath(pattern, key) + "[]", childHeader);
        }
      }
    }
  }

 private:
  const SceneSchema& schema_;
};

}  // namespace

std::string writeResolvedToml(const toml::table& root, const SceneSchema& schema, const std::string& sourceName) {
  std::ostringstream out;
  out << "# Resolved scene: " << sourceName << " with every override applied and every default filled in.\n";
  Writer(schema).body(out, root, "", "");
  return out.str();
}

}  // namespace mfwave::scene
