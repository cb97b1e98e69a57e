#include "methods/collocation/PolynomialBasis.hpp"

#include <string>

#include "core/Error.hpp"

namespace mfwave {

namespace {

// Powers y^p, p = 0..order, of one coordinate.
using PowerTable = std::array<Real, kMaxBasisOrder + 1>;

PowerTable powers(Real y, int order) {
  PowerTable p{};
  p[0] = 1;
  for (int k = 1; k <= order; ++k) p[static_cast<std::size_t>(k)] = p[static_cast<std::size_t>(k - 1)] * y;
  return p;
}

}  // namespace

template <int D>
PolynomialBasis<D>::PolynomialBasis(int order, const char* key) : order_(order) {
  if (order < 0 || order > kMaxBasisOrder) {
    throw InputError(key, "polynomial order " + std::to_string(order) + " is not supported; valid: 0.." +
                              std::to_string(kMaxBasisOrder));
  }
  // Graded order: degree by degree, so the constant comes first and H(0) = e_0.
  for (int degree = 0; degree <= order; ++degree) {
    std::array<int, D> e{};
    // Enumerate all exponent vectors of total `degree`, first axis' exponent decreasing.
    if constexpr (D == 1) {
      e[0] = degree;
      exponents_.push_back(e);
    } else if constexpr (D == 2) {
      for (int a = degree; a >= 0; --a) {
        e[0] = a;
        e[1] = degree - a;
        exponents_.push_back(e);
      }
    } else {
      for (int a = degree; a >= 0; --a) {
        for (int b = degree - a; b >= 0; --b) {
          e[0] = a;
          e[1] = b;
          e[2] = degree - a - b;
          exponents_.push_back(e);
        }
      }
    }
  }
}

template <int D>
int PolynomialBasis<D>::sizeFor(int order) {
  // C(order + D, D)
  int numerator = 1;
  int denominator = 1;
  for (int k = 1; k <= D; ++k) {
    numerator *= order + k;
    denominator *= k;
  }
  return numerator / denominator;
}

template <int D>
void PolynomialBasis<D>::evaluate(const Vec<D>& y, BasisVector& value) const {
  std::array<PowerTable, D> p;
  for (int a = 0; a < D; ++a) p[static_cast<std::size_t>(a)] = powers(y[a], order_);
  value.resize(size());
  for (int t = 0; t < size(); ++t) {
    const std::array<int, D>& e = exponents_[static_cast<std::size_t>(t)];
    Real h = 1;
    for (int a = 0; a < D; ++a)
      h *= p[static_cast<std::size_t>(a)][static_cast<std::size_t>(e[static_cast<std::size_t>(a)])];
    value[t] = h;
  }
}

template <int D>
void PolynomialBasis<D>::evaluate(const Vec<D>& y, int derivatives, Evaluation& out) const {
  // factor[a][d][e] = d^d/dy_a^d y_a^e, tabulated once per point: y^e, e y^(e-1), e (e-1) y^(e-2).
  Real factor[D][3][kMaxBasisOrder + 1];
  for (int a = 0; a < D; ++a) {
    factor[a][0][0] = 1;
    factor[a][1][0] = 0;
    factor[a][2][0] = 0;
    for (int e = 1; e <= order_; ++e) {
      factor[a][0][e] = factor[a][0][e - 1] * y[a];
      factor[a][1][e] = e * factor[a][0][e - 1];
      factor[a][2][e] = e * factor[a][1][e - 1];
    }
  }
  const int n = size();
  out.value.resize(n);
  if (derivatives >= 1)
    for (auto& g : out.gradient) g.resize(n);
  if (derivatives >= 2)
    for (auto& h : out.hessian) h.resize(n);

  // Entry = product over the axes of factor[a][d_a][e_a], with the derivative multi-index d = 0
  // (value), e_j (first derivative) or e_j + e_k (second derivative).
  for (int t = 0; t < n; ++t) {
    const std::array<int, D>& e = exponents_[static_cast<std::size_t>(t)];
    Real value = 1;
    for (int a = 0; a < D; ++a) value *= factor[a][0][e[static_cast<std::size_t>(a)]];
    out.value[t] = value;
    if (derivatives < 1) continue;
    for (int j = 0; j < D; ++j) {
      Real g = 1;
      for (int a = 0; a < D; ++a) g *= factor[a][a == j ? 1 : 0][e[static_cast<std::size_t>(a)]];
      out.gradient[static_cast<std::size_t>(j)][t] = g;
    }
    if (derivatives < 2) continue;
    for (int j = 0; j < D; ++j) {
      for (int k = j; k < D; ++k) {
        Real h = 1;
        for (int a = 0; a < D; ++a) h *= factor[a][(a == j ? 1 : 0) + (a == k ? 1 : 0)][e[static_cast<std::size_t>(a)]];
        out.hessian[static_cast<std::size_t>(symmetricPairIndex<D>(j, k))][t] = h;
      }
    }
  }
}

template class PolynomialBasis<1>;
template class PolynomialBasis<2>;
template class PolynomialBasis<3>;

}  // namespace mfwave
