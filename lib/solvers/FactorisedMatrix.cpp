#include "solvers/FactorisedMatrix.hpp"

#include "core/Error.hpp"

#include <Eigen/LU>
#include <Eigen/SPQRSupport>
#include <Eigen/UmfPackSupport>

#include <algorithm>
#include <cmath>
#include <string>

namespace mfwave {

struct FactorisedMatrix::Sparse {
  // UMFPACK's solve reads the matrix again (iterative refinement), and UmfPackLU only keeps a
  // reference to it: the factorisation owns its copy, declared before the LU so it outlives it.
  SparseMatrix matrix;
  Eigen::UmfPackLU<SparseMatrix> lu;
  // When some unknowns are decoupled (their row and column hold only the diagonal entry), `matrix`
  // is the coupled part alone, `coupled` its unknowns in the full vector, and the rest is solved
  // by `inverseDiagonal` (zero on coupled unknowns). Empty `coupled`: `matrix` is the whole matrix.
  std::vector<Index> coupled;
  Vector inverseDiagonal;
  mutable Vector work, workSolution;

  void solve(const Real* b, Real* x) const {
    if (coupled.empty()) {
      Eigen::Map<Vector>(x, matrix.rows()) = lu.solve(Eigen::Map<const Vector>(b, matrix.rows()));
      return;
    }
    for (Index i = 0; i < inverseDiagonal.size(); ++i) x[i] = inverseDiagonal[i] * b[i];
    for (std::size_t k = 0; k < coupled.size(); ++k) work[static_cast<Index>(k)] = b[coupled[k]];
    workSolution = lu.solve(work);
    for (std::size_t k = 0; k < coupled.size(); ++k) x[coupled[k]] = workSolution[static_cast<Index>(k)];
  }
};

struct FactorisedMatrix::LeastSquares {
  // SPQR works with SuiteSparse_long indices; it keeps its own factors, not a reference.
  using LongMatrix = Eigen::SparseMatrix<Real, Eigen::ColMajor, SuiteSparse_long>;
  Eigen::SPQR<LongMatrix> qr;
};

FactorisedMatrix::FactorisedMatrix() = default;
FactorisedMatrix::~FactorisedMatrix() = default;
FactorisedMatrix::FactorisedMatrix(FactorisedMatrix&&) noexcept = default;
FactorisedMatrix& FactorisedMatrix::operator=(FactorisedMatrix&&) noexcept = default;

namespace {

// |a_ii| > sum_{j != i} |a_ij| for every row.
bool strictlyDiagonallyDominant(const SparseMatrix& a) {
  Vector offDiagonal = Vector::Zero(a.rows());
  Vector diagonal = Vector::Zero(a.rows());
  for (int column = 0; column < a.outerSize(); ++column)
    for (SparseMatrix::InnerIterator it(a, column); it; ++it)
      (it.row() == it.col() ? diagonal[it.row()] : offDiagonal[it.row()]) += std::abs(it.value());
  return (diagonal.array() > offDiagonal.array()).all();
}

bool isDiagonalMatrix(const SparseMatrix& m) {
  for (int k = 0; k < m.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(m, k); it; ++it)
      if (it.row() != it.col() && it.value() != 0) return false;
  return true;
}

// The smallest block size b in {2, 3} for which `m` is block diagonal with at least two b x b
// blocks (every non-zero entry (i, j) has i / b == j / b), or 0.
int blockDiagonalSize(const SparseMatrix& m) {
  for (int b : {2, 3}) {
    if (m.cols() % b != 0 || m.cols() <= b) continue;
    bool blocks = true;
    for (int k = 0; k < m.outerSize() && blocks; ++k)
      for (SparseMatrix::InnerIterator it(m, k); it; ++it)
        if (it.row() / b != it.col() / b && it.value() != 0) {
          blocks = false;
          break;
        }
    if (blocks) return b;
  }
  return 0;
}

}  // namespace

void FactorisedMatrix::factoriseBlocks(const SparseMatrix& a, int blockSize) {
  const Index n = a.cols();
  const Index blocks = n / blockSize;
  const Index entries = static_cast<Index>(blockSize) * blockSize;
  Vector dense = Vector::Zero(blocks * entries);
  for (int k = 0; k < a.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(a, k); it; ++it) {
      const Index block = it.row() / blockSize;
      dense[block * entries + (it.col() % blockSize) * blockSize + it.row() % blockSize] += it.value();
    }
  inverseBlocks_.resize(blocks * entries);
  for (Index block = 0; block < blocks; ++block) {
    const Eigen::Map<const Eigen::MatrixXd> matrix(dense.data() + block * entries, blockSize, blockSize);
    const Eigen::PartialPivLU<Eigen::MatrixXd> lu(matrix);
    // rcond is not finite for a block with a zero pivot. 1e-10: the condition number at which the
    // UMFPACK path's test solve (error about cond * 1e-16, accepted below 1e-6) gives up.
    if (!(lu.rcond() > 1e-10))
      throw Error(what_ + " is singular: diagonal block " + std::to_string(block) + " (rows " +
                  std::to_string(block * blockSize) + " to " + std::to_string((block + 1) * blockSize - 1) +
                  ") has reciprocal condition " + std::to_string(lu.rcond()));
    Eigen::Map<Eigen::MatrixXd>(inverseBlocks_.data() + block * entries, blockSize, blockSize) = lu.inverse();
  }
  blockSize_ = blockSize;
}

template <int B>
void FactorisedMatrix::solveBlocks(const Real* b, Real* x) const {
  using Block = Eigen::Matrix<Real, B, B>;
  using Segment = Eigen::Matrix<Real, B, 1>;
  const Index blocks = size_ / B;
  for (Index block = 0; block < blocks; ++block)
    Eigen::Map<Segment>(x + block * B).noalias() =
        Eigen::Map<const Block>(inverseBlocks_.data() + block * B * B) * Eigen::Map<const Segment>(b + block * B);
}

void FactorisedMatrix::factorise(const SparseMatrix& a, const std::string& what) {
  if (a.rows() < a.cols())
    throw Error(what + " is " + std::to_string(a.rows()) + " x " + std::to_string(a.cols()) +
                ": fewer rows than unknowns");
  what_ = what;
  size_ = -1;
  rows_ = -1;
  sparse_.reset();
  leastSquares_.reset();
  inverseDiagonal_.resize(0);
  inverseBlocks_.resize(0);
  blockSize_ = 0;
  const Index n = a.cols();

  if (a.rows() > a.cols()) {
    auto ls = std::make_unique<LeastSquares>();
    LeastSquares::LongMatrix copy = a.cast<Real>();
    copy.makeCompressed();
    ls->qr.compute(copy);
    if (ls->qr.info() != Eigen::Success) throw Error(what + " could not be factorised by SuiteSparseQR");
    if (static_cast<Index>(ls->qr.rank()) < n)
      throw Error(what + " is rank-deficient: rank " + std::to_string(ls->qr.rank()) + " for " + std::to_string(n) +
                  " unknowns");
    leastSquares_ = std::move(ls);
    size_ = n;
    rows_ = a.rows();
    return;
  }

  if (isDiagonalMatrix(a)) {
    // A diagonal matrix needs no factorisation: one reciprocal per row, exact and O(n).
    const Vector diagonal = a.diagonal();
    for (Index i = 0; i < n; ++i)
      if (!(std::isfinite(diagonal[i]) && diagonal[i] != 0))
        throw Error(what + " is singular: diagonal entry " + std::to_string(i) + " is " +
                    std::to_string(diagonal[i]));
    inverseDiagonal_ = diagonal.cwiseInverse();
    size_ = rows_ = n;
    return;
  }

  if (const int blockSize = blockDiagonalSize(a)) {
    factoriseBlocks(a, blockSize);
    size_ = rows_ = n;
    return;
  }

  auto sparse = std::make_unique<Sparse>();
  // Dashpots on a boundary couple a few unknowns; the others keep a diagonal row and column
  // (M + dt/2 C of central difference). Those are solved by a reciprocal, and UMFPACK sees only
  // the coupled block, so a solve costs in proportion to the boundary layer, not the body.
  std::vector<char> isCoupled(static_cast<std::size_t>(n), 0);
  for (int column = 0; column < a.outerSize(); ++column)
    for (SparseMatrix::InnerIterator it(a, column); it; ++it)
      if (it.row() != it.col() && it.value() != 0)
        isCoupled[static_cast<std::size_t>(it.row())] = isCoupled[static_cast<std::size_t>(it.col())] = 1;
  const auto coupledCount = static_cast<Index>(std::count(isCoupled.begin(), isCoupled.end(), 1));
  if (coupledCount < n) {
    std::vector<Index> position(static_cast<std::size_t>(n), -1);
    sparse->inverseDiagonal = Vector::Zero(n);
    const Vector diagonal = a.diagonal();
    for (Index i = 0; i < n; ++i) {
      if (isCoupled[static_cast<std::size_t>(i)]) {
        position[static_cast<std::size_t>(i)] = static_cast<Index>(sparse->coupled.size());
        sparse->coupled.push_back(i);
      } else {
        if (!(std::isfinite(diagonal[i]) && diagonal[i] != 0))
          throw Error(what + " is singular: diagonal entry " + std::to_string(i) + " is " + std::to_string(diagonal[i]));
        sparse->inverseDiagonal[i] = 1 / diagonal[i];
      }
    }
    std::vector<Triplet> entries;
    for (int column = 0; column < a.outerSize(); ++column)
      for (SparseMatrix::InnerIterator it(a, column); it; ++it)
        if (isCoupled[static_cast<std::size_t>(it.row())])
          entries.emplace_back(static_cast<int>(position[static_cast<std::size_t>(it.row())]),
                               static_cast<int>(position[static_cast<std::size_t>(it.col())]), it.value());
    sparse->matrix.resize(static_cast<int>(coupledCount), static_cast<int>(coupledCount));
    sparse->matrix.setFromTriplets(entries.begin(), entries.end());
    sparse->work.resize(coupledCount);
  } else {
    sparse->matrix = a;
  }
  sparse->matrix.makeCompressed();
  // UMFPACK's automatic strategy picks its symmetric mode for matrices with a nearly symmetric
  // pattern and then accepts diagonal pivots down to 1e-3 of the column maximum: collocation
  // constraint matrices [Psi_I; B] have such patterns and such pivots, and the factors come out
  // useless (residuals of 1e12 at 161 nodes). The unsymmetric strategy with full partial pivoting
  // is robust for every matrix here and costs little for the banded ones.
  // A strictly diagonally dominant matrix (M + dt/2 C of central difference with dashpots) is
  // safe with diagonal pivots, which keep the fill-in to the pattern: the symmetric strategy.
  // Its solves need no iterative refinement either (well conditioned: the test solve below checks).
  if (strictlyDiagonallyDominant(sparse->matrix)) {
    sparse->lu.umfpackControl()(UMFPACK_STRATEGY) = UMFPACK_STRATEGY_SYMMETRIC;
    sparse->lu.umfpackControl()(UMFPACK_IRSTEP) = 0;
  } else {
    sparse->lu.umfpackControl()(UMFPACK_STRATEGY) = UMFPACK_STRATEGY_UNSYMMETRIC;
    sparse->lu.umfpackControl()(UMFPACK_PIVOT_TOLERANCE) = 1.0;
  }
  sparse->lu.compute(sparse->matrix);
  if (sparse->lu.info() == Eigen::NumericalIssue)
    throw Error(what + " is singular: UMFPACK found a zero pivot (status " +
                std::to_string(sparse->lu.umfpackFactorizeReturncode()) + ")");
  if (sparse->lu.info() != Eigen::Success)
    throw Error(what + " could not be factorised: UMFPACK rejected its structure");
  // A factorisation that cannot reproduce a known solution is useless, whatever UMFPACK's status
  // says: one test solve (cost: one solve) catches it here rather than as a blow-up later.
  const Vector ones = Vector::Ones(sparse->matrix.rows());
  const Real testError = (Vector(sparse->lu.solve(Vector(sparse->matrix * ones))) - ones).norm() / ones.norm();
  if (!(testError < 1e-6))
    throw Error(what + " is too ill-conditioned to factorise reliably: a test solve is off by " +
                std::to_string(testError) + " (relative)");
  sparse_ = std::move(sparse);
  size_ = rows_ = n;
}

void FactorisedMatrix::checkRightHandSide(Index rows) const {
  if (!isFactorised()) throw Error("FactorisedMatrix::solve called before factorise");
  if (rows != rows_)
    throw Error(what_ + ": right-hand side has " + std::to_string(rows) + " rows, expected " + std::to_string(rows_));
}

void FactorisedMatrix::solve(const Vector& b, Vector& x) const {
  checkRightHandSide(b.size());
  if (leastSquares_) {
    x = leastSquares_->qr.solve(b);
  } else if (sparse_) {
    x.resize(size_);
    sparse_->solve(b.data(), x.data());
  } else if (blockSize_ > 0) {
    x.resize(size_);
    if (blockSize_ == 2)
      solveBlocks<2>(b.data(), x.data());
    else
      solveBlocks<3>(b.data(), x.data());
  } else {
    x = inverseDiagonal_.cwiseProduct(b);
  }
}

Vector FactorisedMatrix::solve(const Vector& b) const {
  Vector x;
  solve(b, x);
  return x;
}

Eigen::MatrixXd FactorisedMatrix::solve(const Eigen::MatrixXd& b) const {
  checkRightHandSide(b.rows());
  if (leastSquares_) return leastSquares_->qr.solve(b);
  if (sparse_) {
    Eigen::MatrixXd x(size_, b.cols());
    for (Index column = 0; column < b.cols(); ++column) sparse_->solve(b.col(column).data(), x.col(column).data());
    return x;
  }
  if (blockSize_ > 0) {
    Eigen::MatrixXd x(size_, b.cols());
    for (Index column = 0; column < b.cols(); ++column) {
      if (blockSize_ == 2)
        solveBlocks<2>(b.col(column).data(), x.col(column).data());
      else
        solveBlocks<3>(b.col(column).data(), x.col(column).data());
    }
    return x;
  }
  return inverseDiagonal_.asDiagonal() * b;
}

}  // namespace mfwave
