#pragma once
// Writes a scene table as TOML: keys in the order of the schema (so the resolved scene reads
// like docs/scenes.md), numbers in their shortest exact form (0.05, not 0.050000000000000003),
// sub-tables and arrays of tables as [headers] / [[headers]], inline tables kept inline.

#include "io/scene/SceneSchema.hpp"

#include <toml++/toml.h>

#include <string>

namespace mfwave::scene {

std::string writeResolvedToml(const toml::table& root, const SceneSchema& schema, const std::string& sourceName);

}  // namespace mfwave::scene
