#pragma once
// Numbers in messages: the shortest text that reads back to the same double, so that every layer
// (the scene reader, the time step, the catalogue) writes a value the way a user would type it.

#include "core/Types.hpp"

#include <string>

namespace mfwave {

// Shortest text that reads back to the same double ("0.05", "1e-05" -> "1e-5", "inf", "nan"):
// fixed notation unless it is more than three characters longer than scientific.
std::string shortestNumber(Real value);

}  // namespace mfwave
