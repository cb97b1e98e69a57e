#pragma once
// Command-line overrides of scene keys: --set key.path=value.
//
// The value is read as a TOML value: a number, a boolean, a quoted string, an array [1, 2, 3]
// or an inline table { type = "ricker", peak_frequency = 5 }; a bare word that is not a TOML
// value is taken as a string (component=z, name=run2). The path may index arrays of tables
// (probe[0].component=z); missing tables are created, and an index equal to the number of
// entries appends a new entry. A malformed override throws SceneError with key "--set".

#include <toml++/toml.h>

#include <string>

namespace mfwave {

// Applies one override to `table` and returns the key path it set ("probe[0].component").
std::string applyOverride(toml::table& table, const std::string& assignment);

}  // namespace mfwave
