#pragma once
// Radial-basis (RBF) interpolation shape functions, global and dense (every node acts everywhere).
//
// Without polynomial augmentation the interpolant of nodal values u is u(x) = sum_j lambda_j g_j(x)
// with G lambda = u, G_ij = g(|x_i - x_j|), so u(x) = g(x)^T G^{-1} u and the shape functions are
//   psi(x) = G^{-1} g(x)                    (G symmetric; Luo-Liu-Huang's RBCM, g the inverse multiquadric).
// With augmentation by the polynomials p_l of total degree <= p, u(x) = sum_j lambda_j g_j(x) +
// sum_l mu_l p_l(x) with the saddle-point system
//   [G   P] [lambda]   [u]
//   [P^T 0] [mu    ] = [0],   P_jl = p_l(x_j),
// and psi(x) is the first N entries of A^{-1} [g(x); p(x)] (A symmetric). Such psi reproduce every
// polynomial of degree <= p exactly. Derivatives are exact: psi,j = A^{-1} [g,j; p,j], and the
// same for the Hessian, with the analytic derivatives of g (RadialBasisFunction).
//
// A is factorised once (dense PartialPivLU: the multiquadric's G and the saddle-point matrix are
// indefinite, so Cholesky-type factorisations do not apply). Each evaluation solves for all the
// requested derivatives at once: O(N^2 (1 + D + D(D+1)/2)) per point.
//
// The polynomials are evaluated at (x - centre) / scale, centre and scale from the nodes' bounding
// box, for conditioning; this does not change psi (it is a change of basis of the same space).

#include <Eigen/LU>
#include <optional>
#include <string>

#include "methods/collocation/PolynomialBasis.hpp"
#include "methods/collocation/RadialBasisFunction.hpp"
#include "methods/collocation/ShapeFunctions.hpp"
#include "particles/ParticleSet.hpp"

namespace mfwave {

template <int D>
class RadialBasisShapeFunctions final : public ShapeFunctions<D> {
 public:
  static constexpr int kNoPolynomial = -1;
  // Smallest accepted reciprocal condition estimate of A: below it, A is singular in double precision.
  static constexpr Real kMinReciprocalCondition = 1e-16;

  // polynomialDegree: kNoPolynomial (-1) for none, else 0..3 (InputError("method.polynomial_degree")
  // outside that range, or when the nodes do not determine a polynomial of that degree). Throws
  // InputError("method.shape_parameter") when A is numerically singular (c too large for the node
  // spacing, or coincident nodes).
  RadialBasisShapeFunctions(const Coordinates<D>& nodes, const RadialBasisFunction& basis,
                            int polynomialDegree = kNoPolynomial);
  RadialBasisShapeFunctions(const ParticleSet<D>& nodes, const RadialBasisFunction& basis,
                            int polynomialDegree = kNoPolynomial);

  Index nodeCount() const override { return nodeCount_; }
  const RadialBasisFunction& basis() const { return basis_; }
  int polynomialDegree() const { return polynomial_ ? polynomial_->order() : kNoPolynomial; }
  // Reciprocal condition estimate (1-norm) of the factorised interpolation matrix A.
  Real reciprocalCondition() const { return reciprocalCondition_; }
  const Coordinates<D>& nodes() const { return nodes_; }

  void evaluate(const Vec<D>& x, int derivatives, ShapeFunctionValues<D>& out) const override;

  // "radial_basis(inverse_multiquadric, c=0.2)" or "radial_basis(multiquadric, c=0.2, p=1)"
  std::string name() const override;

 private:
  Vec<D> polynomialArgument(const Vec<D>& x) const { return (x - centre_) / scale_; }

  Coordinates<D> nodes_;
  Index nodeCount_;
  RadialBasisFunction basis_;
  std::optional<PolynomialBasis<D>> polynomial_;
  Vec<D> centre_ = Vec<D>::Zero();
  Real scale_ = 1;
  Eigen::PartialPivLU<Eigen::MatrixXd> factor_;
  Real reciprocalCondition_ = 0;
};

extern template class RadialBasisShapeFunctions<1>;
extern template class RadialBasisShapeFunctions<2>;
extern template class RadialBasisShapeFunctions<3>;

}  // namespace mfwave
