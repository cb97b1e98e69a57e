#pragma once
// A sparse matrix factorised once and solved many times: the effective matrix of an implicit
// integrator (Newmark), the mass matrix for the initial acceleration, the constraint matrix of
// strong-form collocation, M + dt/2 C of central difference with implicit dashpots. A diagonal
// matrix (lumped mass, beta = 0) is inverted entry by entry; a block-diagonal one with 2 x 2 or
// 3 x 3 blocks on the diagonal (per-particle dashpots, dof = particle * components + component)
// block by block, because UMFPACK solves such a matrix about 40 times slower than a mat-vec
// (3e5 unknowns: 79 ms per solve against 2 ms, measured) and central difference solves every step;
// another square matrix goes to UMFPACK's sparse LU (Eigen::UmfPackLU), restricted to the unknowns
// that are coupled at all (dashpots couple a boundary layer; the rest is solved by reciprocals),
// with diagonal pivots and no refinement when it is strictly diagonally dominant (M + dt/2 C:
// 2.7 x faster per step for the consistent very weak SPH's dashpots); a tall matrix (more
// collocation rows than unknowns) is solved in the least-squares sense by SuiteSparseQR
// (Eigen::SPQR). SuiteSparse stays out of this header (pimpl).

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

  // Factorises `a` (square, or tall: rows > columns). `what` describes the matrix in error
  // messages ("Newmark effective matrix M + gamma dt C + beta dt^2 K"). Throws mfwave::Error if `a`
  // is singular (a zero or non-finite diagonal entry of a diagonal matrix; a singular diagonal
  // block; UMFPACK's singular warning) or, when tall, rank-deficient.
  void factorise(const SparseMatrix& a, const std::string& what);

  // x = A^{-1} b (square) or the least-squares solution of A x = b (tall). b and x must be
  // distinct vectors.
  void solve(const Vector& b, Vector& x) const;
  Vector solve(const Vector& b) const;
  // The same for several right-hand sides (columns of b).
  Eigen::MatrixXd solve(const Eigen::MatrixXd& b) const;

  bool isFactorised() const { return size_ >= 0; }
  bool isDiagonal() const { return inverseDiagonal_.size() > 0 || size_ == 0; }
  // 2 or 3 when solved block by block (at least two blocks), 0 otherwise.
  int blockSize() const { return blockSize_; }
  bool isLeastSquares() const { return static_cast<bool>(leastSquares_); }
  Index size() const { return size_; }   // columns: the size of x
  Index rows() const { return rows_; }   // the size of b

 private:
  struct Sparse;
  struct LeastSquares;
  std::unique_ptr<Sparse> sparse_;              // UMFPACK factorisation (non-diagonal square)
  std::unique_ptr<LeastSquares> leastSquares_;  // SPQR factorisation (tall)
  Vector inverseDiagonal_;                      // diagonal matrices only
  Vector inverseBlocks_;                        // block-diagonal: the inverse blocks, column-major, one after another
  int blockSize_ = 0;
  Index size_ = -1;
  Index rows_ = -1;
  std::string what_;
  void checkRightHandSide(Index rows) const;
  void factoriseBlocks(const SparseMatrix& a, int blockSize);
  template <int B>
  void solveBlocks(const Real* b, Real* x) const;
};

}  // namespace mfwave
