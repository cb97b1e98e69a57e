#pragma once
// Reference answers for the neighbour tests: O(N^2) searches with the same strict rule
// |x_i - x_j| < R, and seeded random clouds.

#include "neighbours/NeighbourList.hpp"
#include "particles/ParticleSet.hpp"

#include <random>
#include <vector>

namespace mfwave::testing {

template <int D>
Real distanceSquared(const Coordinates<D>& x, Index i, const Vec<D>& y) {
  Real d2 = 0;
  for (std::size_t a = 0; a < static_cast<std::size_t>(D); ++a) {
    const Real d = x[a][static_cast<std::size_t>(i)] - y[static_cast<Eigen::Index>(a)];
    d2 += d * d;
  }
  return d2;
}

template <int D>
Vec<D> pointOf(const Coordinates<D>& x, Index i) {
  Vec<D> p;
  for (int a = 0; a < D; ++a) p[a] = x[static_cast<std::size_t>(a)][static_cast<std::size_t>(i)];
  return p;
}

// Sorted indices j with |y - x_j| < radius.
template <int D>
std::vector<Index> bruteNeighbours(const Coordinates<D>& x, const Vec<D>& y, Real radius) {
  std::vector<Index> found;
  const Index n = static_cast<Index>(x[0].size());
  for (Index j = 0; j < n; ++j) {
    if (distanceSquared<D>(x, j, y) < radius * radius) found.push_back(j);
  }
  return found;
}

template <int D>
NeighbourList bruteNeighbourList(const Coordinates<D>& x, Real radius) {
  NeighbourList list;
  list.offsets.push_back(0);
  const Index n = static_cast<Index>(x[0].size());
  for (Index i = 0; i < n; ++i) {
    const std::vector<Index> row = bruteNeighbours<D>(x, pointOf<D>(x, i), radius);
    list.indices.insert(list.indices.end(), row.begin(), row.end());
    list.offsets.push_back(static_cast<Index>(list.indices.size()));
  }
  return list;
}

// n points uniform in [lower, upper)^D from a fixed seed.
template <int D>
Coordinates<D> randomCloud(Index n, Real lower, Real upper, unsigned seed) {
  std::mt19937_64 engine(seed);
  std::uniform_real_distribution<Real> uniform(lower, upper);
  Coordinates<D> x;
  for (auto& axis : x) axis.resize(static_cast<std::size_t>(n));
  for (Index i = 0; i < n; ++i) {
    for (auto& axis : x) axis[static_cast<std::size_t>(i)] = uniform(engine);
  }
  return x;
}

}  // namespace mfwave::testing
