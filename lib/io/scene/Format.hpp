#pragma once
// Small text helpers shared by the scene reader: numbers for messages and TOML literals,
// the closest valid name for "did you mean" suggestions, lists for messages.

#include "core/Error.hpp"
#include "core/Types.hpp"

#include <optional>
#include <string>
#include <vector>

namespace mfwave::scene {

// Shortest text that reads back to the same double ("0.05", "1e-05", "inf").
std::string formatNumber(Real value);
// The same as a TOML float literal: always with a '.', an exponent, inf or nan ("1.0", "0.05").
std::string tomlNumber(Real value);
// A TOML basic string literal with escapes.
std::string tomlString(const std::string& text);
// "[0.0, 1.5]" / "[\"-x\", \"+x\"]" / "[false, true]".
std::string tomlArray(const std::vector<Real>& values);
std::string tomlArray(const std::vector<std::string>& values);
std::string tomlArray(const std::vector<bool>& values);
// "(0.5, 0.5, 1)" for messages.
std::string formatPoint(const std::vector<Real>& x);
template <int D>
std::string formatPoint(const Vec<D>& x) {
  return formatPoint(std::vector<Real>(x.data(), x.data() + D));
}
// A scene's number array (a point, a vector) as a D-vector: its first D entries, missing ones 0.
template <int D>
Vec<D> vectorOf(const std::vector<Real>& values) {
  Vec<D> v = Vec<D>::Zero();
  for (int i = 0; i < D && i < static_cast<int>(values.size()); ++i) v[i] = values[static_cast<std::size_t>(i)];
  return v;
}
// "a, b, c".
std::string joinNames(const std::vector<std::string>& names, const std::string& separator = ", ");

// Optimal-string-alignment edit distance (insertions, deletions, substitutions and adjacent
// transpositions all cost 1).
std::size_t editDistance(const std::string& a, const std::string& b);
// The candidate closest to `word` if it is close enough to be a likely typo (distance at most
// max(1, |word| / 3)); the first of equally close candidates.
std::optional<std::string> closestMatch(const std::string& word, const std::vector<std::string>& candidates);

// The problem part of an InputError's message (what() without the leading "key: ").
std::string problemOf(const InputError& error);

}  // namespace mfwave::scene
