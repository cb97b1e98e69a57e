#pragma once
// Reproducing-kernel (RK) shape functions of order m (Luo-Liu-Huang eqs. (2)-(6)):
//
//   psi_i(x) = H(0)^T M(x)^{-1} H(x - x_i) phi_a(x - x_i),                        eq. (2)
//   M(x)     = sum_i H(x - x_i) H(x - x_i)^T phi_a(x - x_i),                       eq. (3)
//
// H the complete polynomial basis of total degree <= m in D variables (eq. (4), PolynomialBasis),
// phi_a a kernel of support radius a (by default the cubic B-spline of eq. (6)). They reproduce
// every polynomial of degree <= m exactly: sum_i psi_i(x) p(x_i) = p(x).
//
// Scaling. H is evaluated at y_i = (x - x_i) / a instead of x - x_i, which keeps the entries of M
// of order 1 whatever the units and the order (unscaled, the degree-3 moments of a 0.01 m support
// are 1e-6 times the degree-0 ones and M is needlessly ill-conditioned). It does not change psi:
// H((x - x_i)/a) = S H(x - x_i) with S = diag(a^-|alpha|), so M_s = S M S, and since S H(0) = H(0),
// psi_s = H(0)^T S^{-1} M^{-1} S^{-1} S H(x - x_i) phi = psi. Likewise the kernel's normalisation
// constant cancels between M^{-1} and phi.
//
// Derivatives are exact: with b(x) = M^{-1} H(0) (so psi_i = b^T H_i phi_i), differentiating
// M b = H(0) gives b,j = -M^{-1} M,j b and b,jk = -M^{-1} (M,jk b + M,j b,k + M,k b,j); no finite
// differences. M is factorised once per point (LDLT) and reused for all these solves. The products
// M,j b and friends are accumulated as vectors node by node, never as matrices, so first and second
// derivatives cost O(N K D^2) on top of the O(N K^2) moment matrix (N nodes in the support, K terms).

#include <memory>
#include <string>

#include "kernels/Kernel.hpp"
#include "methods/collocation/PolynomialBasis.hpp"
#include "methods/collocation/ShapeFunctions.hpp"
#include "neighbours/CellList.hpp"
#include "particles/ParticleSet.hpp"

namespace mfwave {

template <int D>
class ReproducingKernelShapeFunctions final : public ShapeFunctions<D> {
 public:
  // Smallest accepted reciprocal condition estimate of the (scaled) moment matrix.
  static constexpr Real kMinReciprocalCondition = 1e-12;

  // Nodes, basis order m (0..3; InputError("method.order") otherwise) and the cubic B-spline
  // window of Luo-Liu-Huang eq. (6) with support radius a (InputError("method.support_radius")
  // unless a > 0 and finite).
  ReproducingKernelShapeFunctions(const Coordinates<D>& nodes, int order, Real supportRadius);
  ReproducingKernelShapeFunctions(const ParticleSet<D>& nodes, int order, Real supportRadius);
  // Any kernel of the kernel library (a std::unique_ptr converts); its supportRadius() is the
  // support. Throws InputError("method.kernel") for a null kernel or one of another dimension.
  ReproducingKernelShapeFunctions(const Coordinates<D>& nodes, int order, std::shared_ptr<const Kernel> kernel);
  ReproducingKernelShapeFunctions(const ParticleSet<D>& nodes, int order, std::shared_ptr<const Kernel> kernel);

  Index nodeCount() const override { return nodeCount_; }
  int order() const { return basis_.order(); }
  // Number of basis terms K = C(m + D, D): the fewest nodes a support may hold.
  int basisSize() const { return basis_.size(); }
  Real supportRadius() const { return supportRadius_; }
  const Kernel& kernel() const { return *kernel_; }
  const Coordinates<D>& nodes() const { return nodes_; }

  // Throws InputError("method.support", ...) naming x when fewer than basisSize() nodes lie within
  // the support radius of x or the moment matrix is too ill-conditioned (reciprocal condition
  // estimate below kMinReciprocalCondition).
  void evaluate(const Vec<D>& x, int derivatives, ShapeFunctionValues<D>& out) const override;

  // "reproducing_kernel(m=2, cubic_b_spline, a=0.25)"
  std::string name() const override;

 private:
  [[noreturn]] void throwSingular(const Vec<D>& x, std::size_t count, Real reciprocalCondition) const;

  Coordinates<D> nodes_;
  Index nodeCount_;
  PolynomialBasis<D> basis_;
  std::shared_ptr<const Kernel> kernel_;
  Real supportRadius_;
  CellList<D> cells_;
};

extern template class ReproducingKernelShapeFunctions<1>;
extern template class ReproducingKernelShapeFunctions<2>;
extern template class ReproducingKernelShapeFunctions<3>;

}  // namespace mfwave
