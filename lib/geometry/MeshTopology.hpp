#pragma once
// The checks that make a triangle list the boundary of a solid: closed (every edge shared by
// exactly two triangles, so inside and outside are defined) and consistently oriented (those two
// traverse it in opposite directions, so one normal per triangle points out). A mesh that fails
// gives a fill or a ray test nonsense far from the defect, so it is refused when read.

#include "core/Types.hpp"

#include <array>
#include <string>
#include <vector>

namespace mfwave {

// Throws InputError(key, ...) for no triangles, a vertex index out of [0, vertexCount), a triangle
// repeating a vertex, boundary edges (an open mesh: says how many), edges of more than two
// triangles, or edges both triangles traverse the same way (inconsistent orientation).
void checkClosedOrientedSurface(Index vertexCount, const std::vector<std::array<Index, 3>>& triangles,
                                const std::string& key);

}  // namespace mfwave
