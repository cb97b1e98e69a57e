#include "methods/collocation/ReproducingKernelShapeFunctions.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/Error.hpp"
#include "kernels/CubicBSplineKernel.hpp"

namespace mfwave {

namespace {

// The moment matrix on the stack (K <= 20): no heap allocation per point.
using MomentMatrix = Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor, kMaxBasisSize, kMaxBasisSize>;

Real checkedSupportRadius(Real a) {
  if (!(a > 0) || !std::isfinite(a)) {
    std::ostringstream text;
    text << "the support radius must be positive and finite, got " << a;
    throw InputError("method.support_radius", text.str());
  }
  return a;
}

template <int D>
std::shared_ptr<const Kernel> checkedKernel(std::shared_ptr<const Kernel> kernel) {
  if (!kernel) throw InputError("method.kernel", "no kernel given");
  if (kernel->dimension() != D) {
    throw InputError("method.kernel", std::string("the kernel '") + kernel->name() + "' is " +
                                          std::to_string(kernel->dimension()) + "-dimensional, the nodes " +
                                          std::to_string(D) + "-dimensional");
  }
  return kernel;
}

}  // namespace

template <int D>
ReproducingKernelShapeFunctions<D>::ReproducingKernelShapeFunctions(const Coordinates<D>& nodes, int order,
                                                                    Real supportRadius)
    : ReproducingKernelShapeFunctions(nodes, order,
                                      std::make_shared<CubicBSplineKernel>(D, checkedSupportRadius(supportRadius))) {}

template <int D>
ReproducingKernelShapeFunctions<D>::ReproducingKernelShapeFunctions(const ParticleSet<D>& nodes, int order,
                                                                    Real supportRadius)
    : ReproducingKernelShapeFunctions(nodes.coordinates(), order, supportRadius) {}

template <int D>
ReproducingKernelShapeFunctions<D>::ReproducingKernelShapeFunctions(const ParticleSet<D>& nodes, int order,
                                                                    std::shared_ptr<const Kernel> kernel)
    : ReproducingKernelShapeFunctions(nodes.coordinates(), order, std::move(kernel)) {}

template <int D>
ReproducingKernelShapeFunctions<D>::ReproducingKernelShapeFunctions(const Coordinates<D>& nodes, int order,
                                                                    std::shared_ptr<const Kernel> kernel)
    : nodes_(nodes),
      nodeCount_(checkedNodeCount<D>(nodes_)),
      basis_(order, "method.order"),
      kernel_(checkedKernel<D>(std::move(kernel))),
      supportRadius_(kernel_->supportRadius()),
      cells_(nodes_, supportRadius_) {}

template <int D>
std::string ReproducingKernelShapeFunctions<D>::name() const {
  std::ostringstream text;
  text << "reproducing_kernel(m=" << order() << ", " << kernel_->name() << ", a=" << supportRadius_ << ")";
  return text.str();
}

template <int D>
void ReproducingKernelShapeFunctions<D>::throwSingular(const Vec<D>& x, std::size_t count,
                                                       Real reciprocalCondition) const {
  std::ostringstream text;
  text << "moment matrix is singular at x = " << formatPoint<D>(x);
  if (count >= static_cast<std::size_t>(basisSize())) {
    text << " (or too ill-conditioned: reciprocal condition estimate " << reciprocalCondition << " < "
         << kMinReciprocalCondition << ")";
  }
  text << ": " << count << " nodes within the support radius a = " << supportRadius_ << ", the order-" << order()
       << " basis needs at least " << basisSize();
  if (count >= static_cast<std::size_t>(basisSize())) text << " in general position";
  text << "; increase the support";
  throw InputError("method.support", text.str());
}

template <int D>
void ReproducingKernelShapeFunctions<D>::evaluate(const Vec<D>& x, int derivatives, ShapeFunctionValues<D>& out) const {
  this->checkDerivatives(derivatives);

  // The nodes whose window covers x (|x - x_i| < a), in increasing index order.
  out.nodes.clear();
  cells_.forEachNeighbour(x, supportRadius_, [&out](Index j, Real) { out.nodes.push_back(j); });
  std::sort(out.nodes.begin(), out.nodes.end());
  const std::size_t n = out.nodes.size();
  const int terms = basis_.size();
  if (n < static_cast<std::size_t>(terms)) throwSingular(x, n, 0);
  resizeShapeFunctionValues(out, n, derivatives);

  // Everything below works in the scaled variable y = (x - x_i) / a, so all quantities are of
  // order 1: derivatives with respect to y are a (resp. a^2) times those with respect to x. The
  // kernel values phi_i and their y-derivatives are computed once and kept in the workspace.
  const Real a = supportRadius_;
  constexpr std::size_t stride = 1 + D + D * D;
  out.workspace.resize(n * stride);
  auto separation = [&](std::size_t k) {  // x - x_i for node i = out.nodes[k]
    Vec<D> r;
    const auto i = static_cast<std::size_t>(out.nodes[k]);
    for (int c = 0; c < D; ++c) r[c] = x[c] - nodes_[static_cast<std::size_t>(c)][i];
    return r;
  };
  auto offset = [&](std::size_t k) -> Vec<D> { return separation(k) / a; };  // y_i = (x - x_i) / a
  for (std::size_t k = 0; k < n; ++k) {
    const Vec<D> r = separation(k);
    Real* w = out.workspace.data() + k * stride;
    w[0] = kernel_->value(r);
    if (derivatives >= 1) Eigen::Map<Vec<D>>(w + 1) = a * kernel_->gradient(r);
    if (derivatives >= 2) Eigen::Map<Mat<D>>(w + 1 + D) = (a * a) * kernel_->hessian(r);
  }
  auto phi = [&](std::size_t k) { return out.workspace[k * stride]; };
  auto phiGradient = [&](std::size_t k, int j) { return out.workspace[k * stride + 1 + static_cast<std::size_t>(j)]; };
  auto phiHessian = [&](std::size_t k, int j, int l) {
    return out.workspace[k * stride + 1 + D + static_cast<std::size_t>(j + D * l)];
  };

  // Moment matrix, Luo-Liu-Huang eq. (3): M = sum_i H_i H_i^T phi_i (lower triangle).
  typename PolynomialBasis<D>::Evaluation h;
  MomentMatrix moment = MomentMatrix::Zero(terms, terms);
  for (std::size_t k = 0; k < n; ++k) {
    basis_.evaluate(offset(k), h.value);
    moment.template selfadjointView<Eigen::Lower>().rankUpdate(h.value, phi(k));
  }
  const Eigen::LDLT<MomentMatrix, Eigen::Lower> factor(moment);
  // Eigen's LDLT solves with zero pivots as a pseudo-inverse, so its condition estimate misses an
  // exactly singular M (e.g. all nodes on a line through x in 2-D). The pivot ratio min D / max D
  // catches that case, and never rejects a matrix rcond accepts: for a positive semi-definite M
  // every pivot lies between the extreme eigenvalues, so min D / max D >= 1 / cond_2(M).
  const Real largestPivot = factor.vectorD().cwiseAbs().maxCoeff();
  const Real pivotRatio = largestPivot > 0 ? factor.vectorD().minCoeff() / largestPivot : 0;
  const Real reciprocalCondition = std::min(factor.rcond(), pivotRatio);
  if (factor.info() != Eigen::Success || !(reciprocalCondition >= kMinReciprocalCondition)) {
    throwSingular(x, n, reciprocalCondition);
  }

  // b = M^{-1} H(0), H(0) = e_0 (eq. (5)); psi_i = b^T H_i phi_i (eq. (2)).
  BasisVector unit = BasisVector::Zero(terms);
  unit[0] = 1;
  const BasisVector b = factor.solve(unit);

  if (derivatives == 0) {
    for (std::size_t k = 0; k < n; ++k) {
      basis_.evaluate(offset(k), h.value);
      out.value[k] = phi(k) * h.value.dot(b);
    }
    return;
  }

  // With w_i = H_i phi_i: M = sum_i H_i w_i^T, psi_i = w_i . b, and
  //   M,j y  = sum_i [H_i,j (w_i . y) + H_i (w_i,j . y)],
  //   M,j b  = sum_i [H_i,j psi_i + H_i (w_i,j . b)],                 b,j = -M^{-1} M,j b.
  // This pass computes psi_i, w_i,j . b (kept in gradient[k] for the next pass) and M,j b.
  std::array<BasisVector, D> rhs1;
  for (auto& v : rhs1) v = BasisVector::Zero(terms);
  for (std::size_t k = 0; k < n; ++k) {
    basis_.evaluate(offset(k), 1, h);
    const Real hb = h.value.dot(b);
    const Real psi = phi(k) * hb;
    out.value[k] = psi;
    for (int j = 0; j < D; ++j) {
      const auto sj = static_cast<std::size_t>(j);
      const Real wjb = phi(k) * h.gradient[sj].dot(b) + phiGradient(k, j) * hb;  // w_i,j . b
      out.gradient[k][j] = wjb;
      rhs1[sj] += psi * h.gradient[sj] + wjb * h.value;
    }
  }
  std::array<BasisVector, D> bj;
  for (int j = 0; j < D; ++j) bj[static_cast<std::size_t>(j)] = -factor.solve(rhs1[static_cast<std::size_t>(j)]);

  // psi_i,j = w_i,j . b + w_i . b,j. For the second derivatives,
  //   psi_i,jk = c_ijk + w_i . b,jk,   c_ijk = w_i,jk . b + w_i,j . b,k + w_i,k . b,j,
  //   M,jk b + M,j b,k + M,k b,j = sum_i [H_i,jk psi_i + H_i,j psi_i,k + H_i,k psi_i,j + H_i c_ijk],
  // with w_i,jk = H_i,jk phi_i + H_i,j phi_i,k + H_i,k phi_i,j + H_i phi_i,jk. c_ijk is kept in
  // hessian[k] until b,jk = -M^{-1} (M,jk b + M,j b,k + M,k b,j) is known.
  constexpr int pairs = PolynomialBasis<D>::pairCount;
  std::array<BasisVector, pairs> rhs2;
  if (derivatives >= 2)
    for (auto& v : rhs2) v = BasisVector::Zero(terms);
  for (std::size_t k = 0; k < n; ++k) {
    basis_.evaluate(offset(k), derivatives, h);
    std::array<Real, D> hbj;  // H_i . b,j
    for (int j = 0; j < D; ++j) {
      hbj[static_cast<std::size_t>(j)] = h.value.dot(bj[static_cast<std::size_t>(j)]);
      out.gradient[k][j] += phi(k) * hbj[static_cast<std::size_t>(j)];
    }
    if (derivatives < 2) continue;
    const Real hb = h.value.dot(b);
    const Real psi = out.value[k];
    const Vec<D>& dpsi = out.gradient[k];
    Vec<D> dhb;   // H_i,j . b
    Mat<D> dhbj;  // (j, l): H_i,j . b,l
    for (int j = 0; j < D; ++j) {
      dhb[j] = h.gradient[static_cast<std::size_t>(j)].dot(b);
      for (int l = 0; l < D; ++l)
        dhbj(j, l) = h.gradient[static_cast<std::size_t>(j)].dot(bj[static_cast<std::size_t>(l)]);
    }
    for (int j = 0; j < D; ++j) {
      const auto sj = static_cast<std::size_t>(j);
      for (int l = j; l < D; ++l) {
        const auto sl = static_cast<std::size_t>(l);
        const int p = symmetricPairIndex<D>(j, l);
        const BasisVector& hjl = h.hessian[static_cast<std::size_t>(p)];
        const Real wjlb = phi(k) * hjl.dot(b) + phiGradient(k, l) * dhb[j] + phiGradient(k, j) * dhb[l] +
                          phiHessian(k, j, l) * hb;                           // w_i,jl . b
        const Real wjbl = phi(k) * dhbj(j, l) + phiGradient(k, j) * hbj[sl];  // w_i,j . b,l
        const Real wlbj = phi(k) * dhbj(l, j) + phiGradient(k, l) * hbj[sj];  // w_i,l . b,j
        const Real c = wjlb + wjbl + wlbj;
        out.hessian[k](j, l) = c;
        rhs2[static_cast<std::size_t>(p)] +=
            psi * hjl + dpsi[l] * h.gradient[sj] + dpsi[j] * h.gradient[sl] + c * h.value;
      }
    }
  }

  if (derivatives >= 2) {
    std::array<BasisVector, pairs> bjl;
    for (int p = 0; p < pairs; ++p) bjl[static_cast<std::size_t>(p)] = -factor.solve(rhs2[static_cast<std::size_t>(p)]);
    const Real scale2 = 1 / (a * a);
    for (std::size_t k = 0; k < n; ++k) {
      basis_.evaluate(offset(k), h.value);
      Mat<D>& hess = out.hessian[k];
      for (int j = 0; j < D; ++j) {
        for (int l = j; l < D; ++l) {
          const int p = symmetricPairIndex<D>(j, l);
          hess(j, l) = scale2 * (hess(j, l) + phi(k) * h.value.dot(bjl[static_cast<std::size_t>(p)]));
          hess(l, j) = hess(j, l);
        }
      }
    }
  }
  // Back from y-derivatives to x-derivatives.
  const Real scale1 = 1 / a;
  for (std::size_t k = 0; k < n; ++k) out.gradient[k] *= scale1;
}

template class ReproducingKernelShapeFunctions<1>;
template class ReproducingKernelShapeFunctions<2>;
template class ReproducingKernelShapeFunctions<3>;

}  // namespace mfwave
