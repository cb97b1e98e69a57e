#pragma once
// Complete polynomial basis of total degree <= m in D variables: H(y) = [y^alpha], |alpha| <= m.
//
// This is Luo-Liu-Huang eq. (4), H^T = [1, y, y^2, ..., y^m], generalised to D variables: every
// monomial y^alpha = y_1^alpha_1 ... y_D^alpha_D with alpha_1 + ... + alpha_D <= m, C(m + D, D)
// of them. They are in graded order (degree 0, then 1, ...; within a degree lexicographic with the
// first axis' exponent decreasing), so entry 0 is the constant 1 and H(0) = e_0 (eq. (5)).
//
// The RK moment matrix uses it with y = (x - x_i) / a (scaled by the support radius, for
// conditioning) and the RBF augmentation with y = (x - centre) / scale. Derivatives here are with
// respect to y; the caller applies the chain-rule factors 1/a and 1/a^2.

#include <Eigen/Core>
#include <array>
#include <vector>

#include "core/Types.hpp"

namespace mfwave {

// Largest supported degree and the largest basis (degree 3 in 3-D: C(6, 3) = 20 terms).
inline constexpr int kMaxBasisOrder = 3;
inline constexpr int kMaxBasisSize = 20;

// Basis vectors live on the stack: at most kMaxBasisSize entries, no heap allocation.
using BasisVector = Eigen::Matrix<Real, Eigen::Dynamic, 1, Eigen::ColMajor, kMaxBasisSize, 1>;

// Index of the pair (j, k), j <= k, among the D (D + 1) / 2 distinct second derivatives:
// (0,0), (0,1), ..., (0,D-1), (1,1), ...
template <int D>
constexpr int symmetricPairIndex(int j, int k) {
  if (j > k) return symmetricPairIndex<D>(k, j);
  return j * D - j * (j - 1) / 2 + (k - j);
}

template <int D>
class PolynomialBasis {
  static_assert(D >= 1 && D <= 3, "polynomial bases exist in 1, 2 and 3 dimensions");

 public:
  static constexpr int pairCount = D * (D + 1) / 2;

  struct Evaluation {
    BasisVector value;                           // H(y)
    std::array<BasisVector, D> gradient;         // dH/dy_j
    std::array<BasisVector, pairCount> hessian;  // d2H/dy_j dy_k at symmetricPairIndex(j, k)
  };

  // Throws InputError(key, ...) unless 0 <= order <= kMaxBasisOrder.
  explicit PolynomialBasis(int order, const char* key = "method.order");

  // C(order + D, D): the number of monomials of total degree <= order in D variables.
  static int sizeFor(int order);

  int order() const { return order_; }
  int size() const { return static_cast<int>(exponents_.size()); }
  const std::array<int, D>& exponent(int term) const { return exponents_[static_cast<std::size_t>(term)]; }

  // H(y) into `value` (resized to size()).
  void evaluate(const Vec<D>& y, BasisVector& value) const;
  // H(y) and, for derivatives >= 1, dH/dy_j, for derivatives == 2, d2H/dy_j dy_k.
  void evaluate(const Vec<D>& y, int derivatives, Evaluation& out) const;

 private:
  int order_;
  std::vector<std::array<int, D>> exponents_;
};

extern template class PolynomialBasis<1>;
extern template class PolynomialBasis<2>;
extern template class PolynomialBasis<3>;

}  // namespace mfwave
