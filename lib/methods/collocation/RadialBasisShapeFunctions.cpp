#include "methods/collocation/RadialBasisShapeFunctions.hpp"

#include <Eigen/QR>
#include <algorithm>
#include <numeric>
#include <sstream>

#include "core/Error.hpp"

namespace mfwave {

namespace {

template <int D>
std::optional<PolynomialBasis<D>> makeAugmentation(int degree) {
  if (degree == RadialBasisShapeFunctions<D>::kNoPolynomial) return std::nullopt;
  if (degree < 0 || degree > kMaxBasisOrder) {
    throw InputError("method.polynomial_degree", "polynomial augmentation of degree " + std::to_string(degree) +
                                                     " is not supported; valid: -1 (none), 0.." +
                                                     std::to_string(kMaxBasisOrder));
  }
  return PolynomialBasis<D>(degree, "method.polynomial_degree");
}

}  // namespace

template <int D>
RadialBasisShapeFunctions<D>::RadialBasisShapeFunctions(const ParticleSet<D>& nodes, const RadialBasisFunction& basis,
                                                        int polynomialDegree)
    : RadialBasisShapeFunctions(nodes.coordinates(), basis, polynomialDegree) {}

template <int D>
RadialBasisShapeFunctions<D>::RadialBasisShapeFunctions(const Coordinates<D>& nodes, const RadialBasisFunction& basis,
                                                        int polynomialDegree)
    : nodes_(nodes),
      nodeCount_(checkedNodeCount<D>(nodes_)),
      basis_(basis),
      polynomial_(makeAugmentation<D>(polynomialDegree)) {
  const auto n = static_cast<Eigen::Index>(nodeCount_);
  const Eigen::Index terms = polynomial_ ? polynomial_->size() : 0;
  auto node = [&](Eigen::Index i) {
    Vec<D> xi;
    for (int a = 0; a < D; ++a) xi[a] = nodes_[static_cast<std::size_t>(a)][static_cast<std::size_t>(i)];
    return xi;
  };

  // Centre and half-width of the bounding box: the polynomial argument is of order 1.
  Vec<D> lower = node(0), upper = node(0);
  for (Eigen::Index i = 1; i < n; ++i) {
    lower = lower.cwiseMin(node(i));
    upper = upper.cwiseMax(node(i));
  }
  centre_ = (lower + upper) / 2;
  const Real halfWidth = (upper - lower).maxCoeff() / 2;
  scale_ = halfWidth > 0 ? halfWidth : 1;

  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n + terms, n + terms);
  for (Eigen::Index j = 0; j < n; ++j) {
    const Vec<D> xj = node(j);
    for (Eigen::Index i = j; i < n; ++i) {
      a(i, j) = basis_.profile((node(i) - xj).squaredNorm()).value;
      a(j, i) = a(i, j);
    }
  }
  if (polynomial_) {
    BasisVector p;
    for (Eigen::Index i = 0; i < n; ++i) {
      polynomial_->evaluate(polynomialArgument(node(i)), p);
      a.block(i, n, 1, terms) = p.transpose();
      a.block(n, i, terms, 1) = p;
    }
    // The saddle-point system is solvable only when no non-zero polynomial of the augmentation
    // vanishes at all nodes (P has full column rank).
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(a.block(0, n, n, terms));
    if (qr.rank() < terms) {
      throw InputError("method.polynomial_degree",
                       "the " + std::to_string(n) + " nodes do not determine a polynomial of degree " +
                           std::to_string(polynomial_->order()) + " (rank " + std::to_string(qr.rank()) + " < " +
                           std::to_string(terms) + " terms); lower the degree or add nodes");
    }
  }
  factor_.compute(a);
  reciprocalCondition_ = factor_.rcond();
  if (!(reciprocalCondition_ >= kMinReciprocalCondition)) {
    std::ostringstream text;
    text << "the " << basis_.name() << " interpolation matrix of the " << n
         << " nodes is numerically singular (reciprocal condition estimate " << reciprocalCondition_ << " < "
         << kMinReciprocalCondition << ") for c = " << basis_.shapeParameter()
         << "; decrease the shape parameter (or remove coincident nodes)";
    throw InputError("method.shape_parameter", text.str());
  }
}

template <int D>
std::string RadialBasisShapeFunctions<D>::name() const {
  std::ostringstream text;
  text << "radial_basis(" << basis_.name() << ", c=" << basis_.shapeParameter();
  if (polynomial_) text << ", p=" << polynomial_->order();
  text << ")";
  return text.str();
}

template <int D>
void RadialBasisShapeFunctions<D>::evaluate(const Vec<D>& x, int derivatives, ShapeFunctionValues<D>& out) const {
  this->checkDerivatives(derivatives);
  const auto n = static_cast<std::size_t>(nodeCount_);
  resizeShapeFunctionValues(out, n, derivatives);
  std::iota(out.nodes.begin(), out.nodes.end(), Index{0});

  // Right-hand sides [g(x); p(x)], [g,j(x); p,j(x)], [g,jk(x); p,jk(x)] (j <= k) as columns,
  // solved all at once; rhs and solution live in the workspace.
  constexpr int pairs = PolynomialBasis<D>::pairCount;
  const Eigen::Index columns = 1 + (derivatives >= 1 ? D : 0) + (derivatives >= 2 ? pairs : 0);
  const Eigen::Index terms = polynomial_ ? polynomial_->size() : 0;
  const Eigen::Index rows = static_cast<Eigen::Index>(n) + terms;
  out.workspace.resize(static_cast<std::size_t>(2 * rows * columns));
  Eigen::Map<Eigen::MatrixXd> rhs(out.workspace.data(), rows, columns);
  Eigen::Map<Eigen::MatrixXd> solution(out.workspace.data() + rows * columns, rows, columns);

  for (std::size_t j = 0; j < n; ++j) {
    Vec<D> r;
    for (int a = 0; a < D; ++a) r[a] = x[a] - nodes_[static_cast<std::size_t>(a)][j];
    const RadialBasisFunction::Profile p = basis_.profile(r.squaredNorm());
    const auto row = static_cast<Eigen::Index>(j);
    rhs(row, 0) = p.value;
    if (derivatives >= 1)
      for (int a = 0; a < D; ++a) rhs(row, 1 + a) = 2 * p.first * r[a];  // grad g = 2 f'(s) r
    if (derivatives >= 2) {
      for (int a = 0; a < D; ++a) {
        for (int b = a; b < D; ++b) {  // Hessian g = 2 f'(s) I + 4 f''(s) r r^T
          rhs(row, 1 + D + symmetricPairIndex<D>(a, b)) = (a == b ? 2 * p.first : 0) + 4 * p.second * r[a] * r[b];
        }
      }
    }
  }
  if (polynomial_) {
    typename PolynomialBasis<D>::Evaluation e;
    polynomial_->evaluate(polynomialArgument(x), derivatives, e);
    for (Eigen::Index l = 0; l < terms; ++l) {
      const Eigen::Index row = static_cast<Eigen::Index>(n) + l;
      rhs(row, 0) = e.value[l];
      if (derivatives >= 1)
        for (int a = 0; a < D; ++a) rhs(row, 1 + a) = e.gradient[static_cast<std::size_t>(a)][l] / scale_;
      if (derivatives >= 2)
        for (int p = 0; p < pairs; ++p)
          rhs(row, 1 + D + p) = e.hessian[static_cast<std::size_t>(p)][l] / (scale_ * scale_);
    }
  }

  solution = factor_.solve(rhs);  // A symmetric: psi = A^{-T} [g; p] = A^{-1} [g; p]

  for (std::size_t j = 0; j < n; ++j) {
    const auto row = static_cast<Eigen::Index>(j);
    out.value[j] = solution(row, 0);
    if (derivatives >= 1)
      for (int a = 0; a < D; ++a) out.gradient[j][a] = solution(row, 1 + a);
    if (derivatives >= 2) {
      for (int a = 0; a < D; ++a) {
        for (int b = a; b < D; ++b) {
          out.hessian[j](a, b) = solution(row, 1 + D + symmetricPairIndex<D>(a, b));
          out.hessian[j](b, a) = out.hessian[j](a, b);
        }
      }
    }
  }
}

template class RadialBasisShapeFunctions<1>;
template class RadialBasisShapeFunctions<2>;
template class RadialBasisShapeFunctions<3>;

}  // namespace mfwave
