#pragma once
// A square sparse matrix factorised once and solved many times: the effective matrix of an
// implicit integrator (Newmark) and the mass matrix for the initial acceleration. A diagonal
// matrix (lumped mass, beta = 0) is inverted entry by entry; anything else goes to UMFPACK's
// sparse LU through Eigen::UmfPackLU. UMFPACK stays out of this header (pimpl).

#include "core/Types.hpp"

#include <memory>
#include <string>

namespace mfwave {

class FactorisedMatrix {
 public:
  FactorisedMatrix();
  ~FactorisedMatrix();
  FactorisedMatrix(FactorisedMatrix&&) noexcept;
  FactorisedMatrix& operator=(FactorisedMatrix&&) noexcept;
  FactorisedMatrix(const FactorisedMatrix&) = delete;
  FactorisedMatrix& operator=(const FactorisedMatrix&) = delete;

  // Factorises `a` (square). `what` describes the matrix in error messages
  // ("Newmark effective matrix M + gamma dt C + beta dt^2 K"). Throws mfwave::Error if `a` is
  // singular (a zero or non-finite diagonal entry of a diagonal matrix; UMFPACK's singular warning).
  void factorise(const SparseMatrix& a, const std::string& what);

  // x = A^{-1} b. b and x must be distinct vectors.
  void solve(const Vector& b, Vector& x) const;

  bool isFactorised() const { return size_ >= 0; }
  bool isDiagonal() const { return inverseDiagonal_.size() > 0 || size_ == 0; }
  Index size() const { return size_; }

 private:
  struct Sparse;
  std::unique_ptr<Sparse> sparse_;  // UMFPACK factorisation (non-diagonal matrices only)
  Vector inverseDiagonal_;           // diagonal matrices only
  Index size_ = -1;
  std::string what_;
};

}  // namespace mfwave
