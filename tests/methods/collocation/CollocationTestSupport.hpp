#pragma once
// Test helpers for the collocation shape functions: node lattices on the unit box (regular or
// randomly perturbed, fixed seeds), evaluation points (random inside plus points hugging faces
// and corners), and monomials x^alpha with their first and second derivatives, written out
// independently of the library's PolynomialBasis.

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "core/Types.hpp"
#include "particles/ParticleSet.hpp"

namespace mfwave::testing {

// (cells + 1)^D nodes on [0, 1]^D, spacing dx = 1 / cells; each coordinate moved by a uniform
// random amount in [-perturbation, perturbation] * dx (seeded, so every run sees the same cloud).
template <int D>
Coordinates<D> unitLattice(int cells, Real perturbation, unsigned seed = 12345u) {
  const Real dx = 1.0 / cells;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Real> shift(-perturbation * dx, perturbation * dx);
  Coordinates<D> nodes;
  std::array<int, 3> count{cells + 1, D >= 2 ? cells + 1 : 1, D >= 3 ? cells + 1 : 1};
  for (int k = 0; k < count[2]; ++k)
    for (int j = 0; j < count[1]; ++j)
      for (int i = 0; i < count[0]; ++i) {
        const std::array<int, 3> ijk{i, j, k};
        for (int a = 0; a < D; ++a) {
          const Real base = ijk[static_cast<std::size_t>(a)] * dx;
          nodes[static_cast<std::size_t>(a)].push_back(base + (perturbation > 0 ? shift(rng) : 0.0));
        }
      }
  return nodes;
}

// `interior` uniform random points in [0, 1]^D, then points near the boundary of the cloud:
// every corner of the box moved inwards by 0.05 dx along each axis, and random points on the
// planes 0.02 dx inside each face.
template <int D>
std::vector<Vec<D>> samplePoints(int interior, Real dx, unsigned seed = 777u) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Real> unit(0.0, 1.0);
  std::vector<Vec<D>> points;
  for (int p = 0; p < interior; ++p) {
    Vec<D> x;
    for (int a = 0; a < D; ++a) x[a] = unit(rng);
    points.push_back(x);
  }
  for (int corner = 0; corner < (1 << D); ++corner) {
    Vec<D> x;
    for (int a = 0; a < D; ++a) x[a] = ((corner >> a) & 1) ? 1.0 - 0.05 * dx : 0.05 * dx;
    points.push_back(x);
  }
  for (int a = 0; a < D; ++a) {
    for (const Real side : {0.02 * dx, 1.0 - 0.02 * dx}) {
      Vec<D> x;
      for (int b = 0; b < D; ++b) x[b] = unit(rng);
      x[a] = side;
      points.push_back(x);
    }
  }
  return points;
}

// All exponent vectors alpha with |alpha| <= order.
template <int D>
std::vector<std::array<int, D>> exponentsUpTo(int order) {
  std::vector<std::array<int, D>> result;
  std::array<int, 3> e{0, 0, 0};
  for (e[0] = 0; e[0] <= order; ++e[0])
    for (e[1] = 0; e[1] <= (D >= 2 ? order : 0); ++e[1])
      for (e[2] = 0; e[2] <= (D >= 3 ? order : 0); ++e[2]) {
        if (e[0] + e[1] + e[2] > order) continue;
        std::array<int, D> alpha{};
        for (int a = 0; a < D; ++a) alpha[static_cast<std::size_t>(a)] = e[static_cast<std::size_t>(a)];
        result.push_back(alpha);
      }
  return result;
}

// d^d/dt^d t^e.
inline Real powerDerivative(Real t, int e, int d) {
  if (d > e) return 0;
  Real factor = 1;
  for (int k = 0; k < d; ++k) factor *= e - k;
  return factor * std::pow(t, e - d);
}

// D^beta x^alpha for a derivative multi-index beta given as (up to two) axes.
template <int D>
Real monomial(const std::array<int, D>& alpha, const Vec<D>& x, int axis1 = -1, int axis2 = -1) {
  Real v = 1;
  for (int a = 0; a < D; ++a) {
    const int d = (a == axis1 ? 1 : 0) + (a == axis2 ? 1 : 0);
    v *= powerDerivative(x[a], alpha[static_cast<std::size_t>(a)], d);
  }
  return v;
}

template <int D>
Vec<D> nodePosition(const Coordinates<D>& nodes, Index i) {
  Vec<D> x;
  for (int a = 0; a < D; ++a) x[a] = nodes[static_cast<std::size_t>(a)][static_cast<std::size_t>(i)];
  return x;
}

}  // namespace mfwave::testing
