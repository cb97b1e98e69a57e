// Symmetric and Hermitian problems (SelfAdjointEigenSolver); the general ones are in
// GeneralEigenproblems.cpp, a file of their own so that the two compile in parallel.
#include "solvers/DenseEigenproblems.hpp"

#include "core/Error.hpp"

#include <Eigen/Eigenvalues>

namespace mfwave {
namespace detail {

void requireConverged(Eigen::ComputationInfo info, const std::string& what) {
  if (info != Eigen::Success) throw Error(what + ": the dense eigenvalue solver did not converge");
}

}  // namespace detail

SymmetricEigenpairs symmetricEigenpairs(const Eigen::MatrixXd& a, const std::string& what) {
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(a, Eigen::ComputeEigenvectors);
  detail::requireConverged(solver.info(), what);
  return {solver.eigenvalues(), solver.eigenvectors()};
}

Eigen::VectorXd symmetricEigenvalues(const Eigen::MatrixXd& a, const std::string& what) {
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(a, Eigen::EigenvaluesOnly);
  detail::requireConverged(solver.info(), what);
  return solver.eigenvalues();
}

HermitianEigenpairs hermitianEigenpairs(const Eigen::MatrixXcd& a, const std::string& what) {
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXcd> solver(a, Eigen::ComputeEigenvectors);
  detail::requireConverged(solver.info(), what);
  return {solver.eigenvalues(), solver.eigenvectors()};
}

Eigen::VectorXd hermitianEigenvalues(const Eigen::MatrixXcd& a, const std::string& what) {
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXcd> solver(a, Eigen::EigenvaluesOnly);
  detail::requireConverged(solver.info(), what);
  return solver.eigenvalues();
}

}  // namespace mfwave
