#include "io/scene/KeyDepth.hpp"

#include "io/scene/SceneError.hpp"

namespace mfwave {
namespace {

bool isBareKeyCharacter(char c) {
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
}

}  // namespace

void checkKeyDepth(const std::string& text, const std::string& sourceName) {
  const std::size_t n = text.size();
  std::size_t line = 1, lineStart = 0;
  std::size_t parts = 0;  // of the current dotted chain
  bool afterDot = false;  // the chain ends in '.' and waits for its next part
  std::size_t startLine = 1, startColumn = 1;
  std::size_t i = 0;
  while (i < n) {
    const char c = text[i];
    if (c == '\n') {
      ++line;
      lineStart = ++i;
      parts = 0;
      afterDot = false;
      continue;
    }
    if (c == ' ' || c == '\t' || c == '\r') {
      ++i;
      continue;
    }
    if (c == '#') {
      while (i < n && text[i] != '\n') ++i;
      continue;
    }
    if (c == '.') {
      afterDot = parts > 0;
      if (!afterDot) parts = 0;
      ++i;
      continue;
    }
    const std::size_t tokenLine = line, tokenColumn = i - lineStart + 1;
    if (isBareKeyCharacter(c)) {
      while (i < n && isBareKeyCharacter(text[i])) ++i;
    } else if (c == '"' || c == '\'') {
      // A quoted key or a string value: basic strings take backslash escapes, literal ones do not;
      // tripled quotes open a multi-line string. An unterminated string runs to the end (the TOML
      // parser reports it).
      const bool triple = i + 2 < n && text[i + 1] == c && text[i + 2] == c;
      i += triple ? 3 : 1;
      while (i < n) {
        if (c == '"' && text[i] == '\\') {
          i += 2;
          continue;
        }
        if (text[i] == '\n') {
          if (!triple) break;
          ++line;
          lineStart = i + 1;
        }
        if (text[i] == c && (!triple || (i + 2 < n && text[i + 1] == c && text[i + 2] == c))) {
          i += triple ? 3 : 1;
          break;
        }
        ++i;
      }
    } else {
      parts = 0;
      afterDot = false;
      ++i;
      continue;
    }
    if (afterDot) {
      ++parts;
    } else {
      parts = 1;
      startLine = tokenLine;
      startColumn = tokenColumn;
    }
    afterDot = false;
    if (parts > kMaxKeyParts)
      throw SceneError(sourceName + ":" + std::to_string(startLine) + ":" + std::to_string(startColumn), "(syntax)",
                       "a dotted key of more than " + std::to_string(kMaxKeyParts) +
                           " parts (a table nested that deep); no scene key has more than four");
  }
}

}  // namespace mfwave
