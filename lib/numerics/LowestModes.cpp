#include "numerics/LowestModes.hpp"

#include "core/Error.hpp"
#include "solvers/DenseEigenproblems.hpp"

#include <Eigen/CholmodSupport>
#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <random>

namespace mfwave {

LowestModes lowestModes(const SparseMatrix& stiffness, const Vector& massDiagonal, int count, Real shift,
                        Real tolerance, int maximumIterations, int guard) {
  const Index n = stiffness.rows();
  const Index block = count + guard;
  if (count < 1 || block > n) throw InputError("count", "must be at least 1 and leave room for the guard vectors");
  if (massDiagonal.size() != n || (massDiagonal.array() <= 0).any())
    throw InputError("mass", "must be the positive diagonal of a lumped mass of the stiffness's size");

  LowestModes result;
  result.shift = shift;
  SparseMatrix shifted = stiffness;
  for (Index i = 0; i < n; ++i) shifted.coeffRef(i, i) += shift * massDiagonal[i];
  Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> factor(shifted);
  result.shiftedMatrixPositiveDefinite = factor.info() == Eigen::Success;
  if (!result.shiftedMatrixPositiveDefinite) return result;

  // theta = 1 / (lambda + shift) are the eigenvalues of Op = S A^-1 S, S = M^(1/2), y = S x: the
  // lowest lambda are the largest theta, which subspace iteration finds first.
  const Vector s = massDiagonal.cwiseSqrt();
  auto apply = [&](const Eigen::MatrixXd& y) -> Eigen::MatrixXd {
    const Eigen::MatrixXd rhs = s.asDiagonal() * y;
    return s.asDiagonal() * factor.solve(rhs);
  };
  std::mt19937_64 random(20261125);
  std::normal_distribution<Real> normal;
  Eigen::MatrixXd q(n, block);
  for (Index j = 0; j < block; ++j)
    for (Index i = 0; i < n; ++i) q(i, j) = normal(random);
  q = Eigen::HouseholderQR<Eigen::MatrixXd>(q).householderQ() * Eigen::MatrixXd::Identity(n, block);

  Eigen::VectorXd theta;
  Eigen::MatrixXd w;
  std::vector<Real> residuals(static_cast<std::size_t>(count));
  for (result.iterations = 1; result.iterations <= maximumIterations; ++result.iterations) {
    w = apply(q);
    const Eigen::MatrixXd h = q.transpose() * w;
    const SymmetricEigenpairs ritz = symmetricEigenpairs(0.5 * (h + h.transpose()), "lowestModes (Ritz values)");
    // descending theta = ascending lambda
    theta = ritz.values.reverse();
    const Eigen::MatrixXd vectors = ritz.vectors.rowwise().reverse();
    const Eigen::MatrixXd x = q * vectors, ox = w * vectors;
    bool done = true;
    for (int j = 0; j < count; ++j) {
      // |Op y - theta y| / theta equals |K x - lambda M x|_{M^-1} / ((lambda + shift) |x|_M)
      residuals[static_cast<std::size_t>(j)] = (ox.col(j) - theta[j] * x.col(j)).norm() / std::abs(theta[j]);
      done = done && residuals[static_cast<std::size_t>(j)] < tolerance;
    }
    if (done) {
      result.converged = true;
      break;
    }
    q = Eigen::HouseholderQR<Eigen::MatrixXd>(ox).householderQ() * Eigen::MatrixXd::Identity(n, block);
  }
  result.iterations = std::min(result.iterations, maximumIterations);
  for (int j = 0; j < count; ++j) result.eigenvalues.push_back(1 / theta[j] - shift);
  result.residuals = residuals;
  return result;
}

}  // namespace mfwave
