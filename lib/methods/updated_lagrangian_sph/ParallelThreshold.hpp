#pragma once
// Below this many particles the per-particle loops run on one thread: a pass over a few thousand
// particles takes well under a millisecond, less than waking a team costs when tests share two
// cores (oversubscription made a small test slow before).

#include "core/Types.hpp"

namespace mfwave {

inline constexpr Index kParallelParticles = 2048;

}  // namespace mfwave
