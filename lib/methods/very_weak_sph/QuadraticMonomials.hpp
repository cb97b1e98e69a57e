#pragma once
// The monomials of degree <= 2 in D variables, with value, gradient and (constant) Hessian: the
// basis of the consistency conditions of the consistent variant (ConsistentCorrection.hpp).
// Order: 1, then x_0..x_{D-1}, then x_j x_l for j <= l; (D + 1)(D + 2) / 2 of them.

#include "core/Types.hpp"

#include <array>
#include <vector>

namespace mfwave {

template <int D>
class QuadraticMonomials {
 public:
  static constexpr int count = (D + 1) * (D + 2) / 2;

  QuadraticMonomials() {
    exponents_.push_back({});
    for (int j = 0; j < D; ++j) exponents_.push_back(unit(j));
    for (int j = 0; j < D; ++j)
      for (int l = j; l < D; ++l) {
        std::array<int, D> e = unit(j);
        ++e[static_cast<std::size_t>(l)];
        exponents_.push_back(e);
      }
  }

  Real value(int m, const Vec<D>& x) const { return product(exponents(m), x); }

  Vec<D> gradient(int m, const Vec<D>& x) const {
    Vec<D> g = Vec<D>::Zero();
    for (int j = 0; j < D; ++j) {
      std::array<int, D> e = exponents(m);
      const int power = e[static_cast<std::size_t>(j)];
      if (power == 0) continue;
      --e[static_cast<std::size_t>(j)];
      g[j] = power * product(e, x);
    }
    return g;
  }

  // Degree <= 2, so the Hessian does not depend on x.
  Mat<D> hessian(int m) const {
    Mat<D> hess = Mat<D>::Zero();
    const std::array<int, D>& e = exponents(m);
    for (int j = 0; j < D; ++j)
      for (int l = 0; l < D; ++l) {
        const int ej = e[static_cast<std::size_t>(j)], el = e[static_cast<std::size_t>(l)];
        if (j == l)
          hess(j, j) = ej == 2 ? 2.0 : 0.0;
        else
          hess(j, l) = (ej == 1 && el == 1) ? 1.0 : 0.0;
      }
    return hess;
  }

  const std::array<int, D>& exponents(int m) const { return exponents_[static_cast<std::size_t>(m)]; }

 private:
  static std::array<int, D> unit(int j) {
    std::array<int, D> e{};
    e[static_cast<std::size_t>(j)] = 1;
    return e;
  }
  static Real product(const std::array<int, D>& e, const Vec<D>& x) {
    Real p = 1;
    for (int j = 0; j < D; ++j)
      for (int k = 0; k < e[static_cast<std::size_t>(j)]; ++k) p *= x[j];
    return p;
  }

  std::vector<std::array<int, D>> exponents_;
};

}  // namespace mfwave
