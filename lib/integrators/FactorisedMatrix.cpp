#include "integrators/FactorisedMatrix.hpp"

#include "core/Error.hpp"

#include <Eigen/UmfPackSupport>

#include <cmath>
#include <string>

namespace mfwave {

struct FactorisedMatrix::Sparse {
  // UMFPACK's solve reads the matrix again (iterative refinement), and UmfPackLU only keeps a
  // reference to it: the factorisation owns its copy, declared before the LU so it outlives it.
  SparseMatrix matrix;
  Eigen::UmfPackLU<SparseMatrix> lu;
};

FactorisedMatrix::FactorisedMatrix() = default;
FactorisedMatrix::~FactorisedMatrix() = default;
FactorisedMatrix::FactorisedMatrix(FactorisedMatrix&&) noexcept = default;
FactorisedMatrix& FactorisedMatrix::operator=(FactorisedMatrix&&) noexcept = default;

namespace {

bool isDiagonalMatrix(const SparseMatrix& m) {
  for (int k = 0; k < m.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(m, k); it; ++it)
      if (it.row() != it.col() && it.value() != 0) return false;
  return true;
}

}  // namespace

void FactorisedMatrix::factorise(const SparseMatrix& a, const std::string& what) {
  if (a.rows() != a.cols())
    throw Error(what + " is " + std::to_string(a.rows()) + " x " + std::to_string(a.cols()) + ", not square");
  what_ = what;
  size_ = -1;
  sparse_.reset();
  inverseDiagonal_.resize(0);
  const Index n = a.rows();

  if (isDiagonalMatrix(a)) {
    // A diagonal matrix needs no factorisation: one reciprocal per row, exact and O(n).
    const Vector diagonal = a.diagonal();
    for (Index i = 0; i < n; ++i)
      if (!(std::isfinite(diagonal[i]) && diagonal[i] != 0))
        throw Error(what + " is singular: diagonal entry " + std::to_string(i) + " is " +
                    std::to_string(diagonal[i]));
    inverseDiagonal_ = diagonal.cwiseInverse();
    size_ = n;
    return;
  }

  auto sparse = std::make_unique<Sparse>();
  sparse->matrix = a;
  sparse->matrix.makeCompressed();
  sparse->lu.compute(sparse->matrix);
  if (sparse->lu.info() == Eigen::NumericalIssue)
    throw Error(what + " is singular: UMFPACK found a zero pivot (status " +
                std::to_string(sparse->lu.umfpackFactorizeReturncode()) + ")");
  if (sparse->lu.info() != Eigen::Success)
    throw Error(what + " could not be factorised: UMFPACK rejected its structure");
  sparse_ = std::move(sparse);
  size_ = n;
}

void FactorisedMatrix::solve(const Vector& b, Vector& x) const {
  if (!isFactorised()) throw Error("FactorisedMatrix::solve called before factorise");
  if (b.size() != size_)
    throw Error(what_ + ": right-hand side has size " + std::to_string(b.size()) + ", expected " +
                std::to_string(size_));
  if (!sparse_) {
    x = inverseDiagonal_.cwiseProduct(b);
    return;
  }
  x.resize(size_);
  x = sparse_->lu.solve(b);
}

}  // namespace mfwave
