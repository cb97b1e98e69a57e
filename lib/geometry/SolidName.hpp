#pragma once
// How primitives carry the user's name: checked once at construction, prefixed to every surface
// name ("hole.surface"), and used as the head of the keys their input errors name ("hole.radius",
// or "ball.radius" for an unnamed ball), so a scene error points at the solid the user wrote.

#include <string>

namespace mfwave {

// `name` when it is a valid solid name (empty, or no '.' so "<name>.<surface>" stays readable);
// throws InputError("<kind>.name") otherwise.
std::string checkedSolidName(const std::string& name, const std::string& kind);

// "<name>.<surface>", or `surface` when the primitive has no name.
std::string qualifiedSurfaceName(const std::string& name, const std::string& surface);

// "<name>.<field>" for a named primitive, "<kind>.<field>" for an unnamed one.
std::string solidKey(const std::string& name, const std::string& kind, const std::string& field);

}  // namespace mfwave
