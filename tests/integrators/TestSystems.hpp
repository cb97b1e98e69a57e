#pragma once
// Small systems with exact solutions for the integrator tests.

#include "core/Types.hpp"
#include "systems/LinearSecondOrderSystem.hpp"

#include <cmath>
#include <memory>

namespace mfwave::test {

inline SparseMatrix scalarMatrix(Real value) {
  SparseMatrix m(1, 1);
  m.insert(0, 0) = value;
  return m;
}

// u'' + 2 zeta w u' + w^2 u = 0 as a 1-dof LinearSecondOrderSystem (no damping matrix if zeta = 0).
inline std::unique_ptr<LinearSecondOrderSystem> oscillator(Real w, Real zeta) {
  return std::make_unique<LinearSecondOrderSystem>(scalarMatrix(1), zeta > 0 ? scalarMatrix(2 * zeta * w) : SparseMatrix(),
                                                   scalarMatrix(w * w));
}

// Exact (u, v) at t for u(0) = 1, v(0) = 0, 0 <= zeta < 1.
struct Exact {
  Real u, v;
};
inline Exact oscillatorExact(Real w, Real zeta, Real t) {
  const Real wd = w * std::sqrt(1 - zeta * zeta);
  const Real decay = std::exp(-zeta * w * t);
  return {decay * (std::cos(wd * t) + zeta * w / wd * std::sin(wd * t)), -decay * (w * w / wd) * std::sin(wd * t)};
}

// A fixed-fixed chain of n unit masses and unit springs: M = I, K = tridiag(-1, 2, -1).
// Highest frequency < 2, so the explicit (central-difference) limit is dt < 1.
inline std::unique_ptr<LinearSecondOrderSystem> springChain(int n) {
  std::vector<Triplet> k;
  for (int i = 0; i < n; ++i) {
    k.emplace_back(i, i, 2.0);
    if (i > 0) k.emplace_back(i, i - 1, -1.0);
    if (i + 1 < n) k.emplace_back(i, i + 1, -1.0);
  }
  SparseMatrix stiffness(n, n), mass(n, n);
  stiffness.setFromTriplets(k.begin(), k.end());
  mass.setIdentity();
  return std::make_unique<LinearSecondOrderSystem>(mass, SparseMatrix(), stiffness);
}

// A smooth initial displacement on the chain (a sine bump plus a short-wave component).
inline Vector chainInitialDisplacement(int n) {
  Vector u(n);
  for (int i = 0; i < n; ++i) {
    const Real x = (i + 1.0) / (n + 1.0);
    u[i] = std::sin(M_PI * x) + 0.3 * std::sin(17 * M_PI * x);
  }
  return u;
}

}  // namespace mfwave::test
