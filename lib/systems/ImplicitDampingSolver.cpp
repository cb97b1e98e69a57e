#include "systems/ImplicitDampingSolver.hpp"

#include "systems/LinearSecondOrderSystem.hpp"

namespace mfwave {

void ImplicitDampingSolver::factorise(const LinearSecondOrderSystem& system, Real dt,
                                      const std::vector<Index>& prescribedDofs) {
  system_ = &system;
  prescribedDofs_ = prescribedDofs;
  const SparseMatrix full = system.mass() + (0.5 * dt) * system.damping();
  const Index n = full.rows();
  // column of the coupling matrix for each prescribed dof, -1 for a free one
  std::vector<Index> prescribedColumn(static_cast<size_t>(n), -1);
  for (size_t i = 0; i < prescribedDofs.size(); ++i)
    prescribedColumn[static_cast<size_t>(prescribedDofs[i])] = static_cast<Index>(i);

  std::vector<Triplet> kept, coupled;
  kept.reserve(static_cast<size_t>(full.nonZeros()));
  for (int k = 0; k < full.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(full, k); it; ++it) {
      const Index rowColumn = prescribedColumn[static_cast<size_t>(it.row())];
      const Index column = prescribedColumn[static_cast<size_t>(it.col())];
      if (rowColumn < 0 && column < 0)
        kept.emplace_back(it.row(), it.col(), it.value());
      else if (rowColumn < 0)
        coupled.emplace_back(it.row(), static_cast<int>(column), it.value());
    }
  for (Index dof : prescribedDofs) kept.emplace_back(static_cast<int>(dof), static_cast<int>(dof), 1.0);
  SparseMatrix reduced(n, n);
  reduced.setFromTriplets(kept.begin(), kept.end());
  matrix_.factorise(reduced, "central-difference dashpot matrix M + dt/2 C");
  coupling_.resize(n, static_cast<Index>(prescribedDofs.size()));
  coupling_.setFromTriplets(coupled.begin(), coupled.end());
  rhs_.resize(n);
}

void ImplicitDampingSolver::acceleration(Real t, const Vector& u, const Vector& vHalf,
                                         const Vector& prescribedAcceleration, Vector& a) {
  system_->force(t, rhs_);
  rhs_.noalias() -= system_->stiffness() * u;
  rhs_.noalias() -= system_->damping() * vHalf;
  if (!prescribedDofs_.empty()) {
    if (coupling_.nonZeros() > 0) rhs_.noalias() -= coupling_ * prescribedAcceleration;
    for (size_t i = 0; i < prescribedDofs_.size(); ++i)
      rhs_[prescribedDofs_[i]] = prescribedAcceleration[static_cast<Index>(i)];
  }
  matrix_.solve(rhs_, a);
}

}  // namespace mfwave
