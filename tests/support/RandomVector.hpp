#pragma once
// A reproducible vector of uniform entries in [-1, 1): the state tests feed to operators.

#include "core/Types.hpp"

#include <random>

namespace mfwave::test {

inline Vector randomVector(Index n, unsigned seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<Real> uniform(-1, 1);
  Vector x(n);
  for (Index i = 0; i < n; ++i) x[i] = uniform(random);
  return x;
}

}  // namespace mfwave::test
