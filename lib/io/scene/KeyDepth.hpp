#pragma once
// A guard the TOML reader needs before it sees a scene: toml++ makes a table for every part of a
// dotted key (`a.b.c = 1` is three tables deep), and both its parser and its destructor recurse
// once per level, so a key of a few hundred thousand parts overflows the stack and kills the
// process (SIGSEGV, no message) before any check of ours runs. No mfwave key has more than four
// parts; a scene or an override whose key has more than kMaxKeyParts is refused as a syntax error
// naming where it starts.

#include <cstddef>
#include <string>

namespace mfwave {

inline constexpr std::size_t kMaxKeyParts = 64;

// Throws SceneError("<source>:<line>:<column>", "(syntax)", ...) at the first dotted chain of more
// than kMaxKeyParts parts (bare or quoted keys joined by '.', in a key/value line, a table header or
// an inline table). Strings and comments are skipped; a number such as 1.5 counts as two parts, so
// values never come near the limit. Linear in the text, no recursion.
void checkKeyDepth(const std::string& text, const std::string& sourceName);

}  // namespace mfwave
