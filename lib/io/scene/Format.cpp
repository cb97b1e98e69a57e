#include "io/scene/Format.hpp"

#include "core/NumberText.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>

namespace mfwave::scene {

std::string formatNumber(Real value) { return shortestNumber(value); }

std::string tomlNumber(Real value) {
  std::string text = formatNumber(value);
  if (text.find_first_of(".eni") == std::string::npos) text += ".0";
  return text;
}

std::string tomlString(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      case '\r': out += "\\r"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
          char escape[8];
          std::snprintf(escape, sizeof(escape), "\\u%04x", static_cast<unsigned>(static_cast<unsigned char>(c)));
          out += escape;
        } else {
          out += c;
        }
    }
  }
  return out + "\"";
}

std::string tomlArray(const std::vector<Real>& values) {
  std::string out = "[";
  for (std::size_t i = 0; i < values.size(); ++i) out += (i ? ", " : "") + tomlNumber(values[i]);
  return out + "]";
}

std::string tomlArray(const std::vector<std::string>& values) {
  std::string out = "[";
  for (std::size_t i = 0; i < values.size(); ++i) out += (i ? ", " : "") + tomlString(values[i]);
  return out + "]";
}

std::string tomlArray(const std::vector<bool>& values) {
  std::string out = "[";
  for (std::size_t i = 0; i < values.size(); ++i) out += std::string(i ? ", " : "") + (values[i] ? "true" : "false");
  return out + "]";
}

std::string formatPoint(const std::vector<Real>& x) {
  std::string out = "(";
  for (std::size_t i = 0; i < x.size(); ++i) out += (i ? ", " : "") + formatNumber(x[i]);
  return out + ")";
}

std::string joinNames(const std::vector<std::string>& names, const std::string& separator) {
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i) out += (i ? separator : "") + names[i];
  return out;
}

std::size_t editDistance(const std::string& a, const std::string& b) {
  const std::size_t n = a.size(), m = b.size();
  std::vector<std::vector<std::size_t>> d(n + 1, std::vector<std::size_t>(m + 1, 0));
  for (std::size_t i = 0; i <= n; ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= m; ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= n; ++i) {
    for (std::size_t j = 1; j <= m; ++j) {
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  }
  return d[n][m];
}

std::optional<std::string> closestMatch(const std::string& word, const std::vector<std::string>& candidates) {
  const std::size_t limit = std::max<std::size_t>(1, word.size() / 3);
  std::optional<std::string> best;
  std::size_t bestDistance = limit + 1;
  for (const auto& candidate : candidates) {
    const std::size_t distance = editDistance(word, candidate);
    if (distance < bestDistance) {
      bestDistance = distance;
      best = candidate;
    }
  }
  return best;
}

std::string problemOf(const InputError& error) {
  const std::string message = error.what();
  const std::string prefix = error.key() + ": ";
  return message.compare(0, prefix.size(), prefix) == 0 ? message.substr(prefix.size()) : message;
}

}  // namespace mfwave::scene
