#pragma once
// The scene's language for solids: a CSG expression over named shapes, e.g.
// "box & ground - cavity" or "(layer1 + layer2) - hole". `+` is the union, `-` the difference, `&`
// the intersection; `&` binds tighter than `+` and `-`, which go left to right; parentheses group.
// Names are letters, digits and underscores, resolved by the caller (the scene's [[shape]] entries).

#include "geometry/Csg.hpp"

#include <functional>
#include <string>
#include <vector>

namespace mfwave {

// The solid `text` describes. `lookup(name)` returns the shape of that name or null. Throws
// InputError(key, problem) naming the position for a syntax error, an unknown name (listing the
// known ones, `known`), or an empty expression.
template <int D>
SolidPtr<D> parseSolidExpression(const std::string& text, const std::function<SolidPtr<D>(const std::string&)>& lookup,
                                 const std::vector<std::string>& known, const std::string& key);

// The names an expression uses, in order of first use (for checks before the shapes exist).
std::vector<std::string> solidExpressionNames(const std::string& text);

}  // namespace mfwave
