#include "methods/collocation/ConstrainedCollocationSystem.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/Error.hpp"

namespace mfwave {

namespace {

// The rows `rows` of `m`, in that order.
SparseMatrix selectRows(const SparseMatrix& m, const std::vector<Index>& rows) {
  std::vector<int> newRow(static_cast<std::size_t>(m.rows()), -1);
  for (std::size_t r = 0; r < rows.size(); ++r) newRow[static_cast<std::size_t>(rows[r])] = static_cast<int>(r);
  std::vector<Triplet> t;
  for (int col = 0; col < m.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(m, col); it; ++it) {
      const int r = newRow[static_cast<std::size_t>(it.row())];
      if (r >= 0) t.emplace_back(r, col, it.value());
    }
  SparseMatrix out(static_cast<int>(rows.size()), m.cols());
  out.setFromTriplets(t.begin(), t.end());
  out.makeCompressed();
  return out;
}

}  // namespace

ConstrainedCollocationSystem::~ConstrainedCollocationSystem() = default;

ConstrainedCollocationSystem::ConstrainedCollocationSystem(CollocationSystem system)
    : system_(std::move(system)) {
  for (Index r = 0; r < system_.rows(); ++r)
    (system_.rowKind[static_cast<std::size_t>(r)] == CollocationRowKind::Interior ? interiorRows_ : boundaryRows_)
        .push_back(r);
  if (interiorRows_.empty()) throw InputError("collocation.points", "there is no interior collocation point");
  if (system_.rows() < system_.cols())
    throw InputError("collocation.points", "fewer collocation rows (" + std::to_string(system_.rows()) +
                                               ") than coefficients (" + std::to_string(system_.cols()) + ")");
  psiInterior_ = selectRows(system_.S, interiorRows_) / system_.density;
  aInterior_ = selectRows(system_.A, interiorRows_);
  const SparseMatrix b = selectRows(system_.A, boundaryRows_);
  std::vector<Triplet> t;
  for (int col = 0; col < psiInterior_.outerSize(); ++col) {
    for (SparseMatrix::InnerIterator it(psiInterior_, col); it; ++it) t.emplace_back(it.row(), col, it.value());
    for (SparseMatrix::InnerIterator it(b, col); it; ++it)
      t.emplace_back(static_cast<int>(interiorRows_.size()) + it.row(), col, it.value());
  }
  constraint_.resize(static_cast<int>(system_.rows()), static_cast<int>(system_.cols()));
  constraint_.setFromTriplets(t.begin(), t.end());
  constraint_.makeCompressed();

  solver_.factorise(constraint_, std::string("collocation constraint matrix [Psi_I; B]") +
                                     (isLeastSquares() ? " (least squares)" : ""));
}

Vector ConstrainedCollocationSystem::boundaryData(Real t) const {
  Vector out = Vector::Zero(static_cast<Index>(boundaryRows_.size()));
  if (!system_.load) return out;
  const Vector b = system_.rhs(t);
  for (std::size_t r = 0; r < boundaryRows_.size(); ++r) out[static_cast<Index>(r)] = b[boundaryRows_[r]];
  return out;
}

Vector ConstrainedCollocationSystem::boundaryDataRate(Real t, int order) const {
  if (!system_.load) return Vector::Zero(static_cast<Index>(boundaryRows_.size()));
  const Real e = 1e-4 * std::max<Real>(1, std::abs(t));
  if (order == 1) return (boundaryData(t + e) - boundaryData(t - e)) / (2 * e);
  return (boundaryData(t + e) - 2 * boundaryData(t) + boundaryData(t - e)) / (e * e);
}

Vector ConstrainedCollocationSystem::solveConstraint(const Vector& top, const Vector& bottom) const {
  if (top.size() != size() || bottom.size() != static_cast<Index>(boundaryRows_.size()))
    throw InputError("collocation.values", "expected " + std::to_string(size()) + " interior and " +
                                               std::to_string(boundaryRows_.size()) + " boundary values");
  Vector rhs(constraint_.rows());
  rhs << top, bottom;
  return solver_.solve(rhs);
}

Vector ConstrainedCollocationSystem::coefficients(const Vector& U, Real t) const {
  return solveConstraint(U, boundaryData(t));
}

Vector ConstrainedCollocationSystem::coefficientRates(const Vector& V, Real t) const {
  return solveConstraint(V, boundaryDataRate(t, 1));
}

Vector ConstrainedCollocationSystem::coefficientAccelerations(const Vector& U, Real t) {
  Vector a(size());
  acceleration(t, U, U, a);
  return solveConstraint(a, boundaryDataRate(t, 2));
}

void ConstrainedCollocationSystem::acceleration(Real t, Eigen::Ref<const Vector> u, Eigen::Ref<const Vector>,
                                                Eigen::Ref<Vector> a) {
  const Index nI = size();
  rhs_.resize(constraint_.rows());
  rhs_.head(nI) = u;
  if (system_.load) {
    b_ = system_.rhs(t);
    for (std::size_t r = 0; r < boundaryRows_.size(); ++r) rhs_[nI + static_cast<Index>(r)] = b_[boundaryRows_[r]];
  } else {
    rhs_.tail(static_cast<Index>(boundaryRows_.size())).setZero();
  }
  d_ = solver_.solve(rhs_);
  a.noalias() = aInterior_ * d_;
  if (system_.load)
    for (Index r = 0; r < nI; ++r) a[r] = b_[interiorRows_[static_cast<std::size_t>(r)]] - a[r];
  else
    a = -a;
  a /= system_.density;
}

Eigen::MatrixXd ConstrainedCollocationSystem::constraintAdjoint(const Eigen::MatrixXd& functionals) const {
  if (isLeastSquares())
    throw Error("constraintAdjoint: the collocation constraint matrix is tall (least squares); its adjoint is not "
                "C^{-T}");
  if (functionals.rows() != constraint_.cols())
    throw InputError("collocation.functionals", "expected " + std::to_string(constraint_.cols()) + " rows");
  const SparseMatrix transposed = constraint_.transpose();
  FactorisedMatrix adjoint;
  adjoint.factorise(transposed, "transposed collocation constraint matrix [Psi_I; B]^T");
  return adjoint.solve(functionals);
}

Eigen::MatrixXd ConstrainedCollocationSystem::denseStiffness() const {
  const Index nI = size();
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(constraint_.rows(), nI);
  rhs.topRows(nI).setIdentity();
  const Eigen::MatrixXd x = solver_.solve(rhs);
  return (aInterior_ * x) / system_.density;
}

}  // namespace mfwave
