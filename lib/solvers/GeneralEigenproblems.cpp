// General (non-symmetric) problems: EigenSolver for real matrices, ComplexEigenSolver for complex.
#include "solvers/DenseEigenproblems.hpp"

#include <Eigen/Eigenvalues>

namespace mfwave {

GeneralEigenpairs generalEigenpairs(const Eigen::MatrixXd& a, bool computeVectors, const std::string& what) {
  const Eigen::EigenSolver<Eigen::MatrixXd> solver(a, computeVectors);
  detail::requireConverged(solver.info(), what);
  GeneralEigenpairs result{solver.eigenvalues(), {}};
  if (computeVectors) result.vectors = solver.eigenvectors();
  return result;
}

GeneralEigenpairs generalEigenpairs(const Eigen::MatrixXcd& a, bool computeVectors, const std::string& what) {
  const Eigen::ComplexEigenSolver<Eigen::MatrixXcd> solver(a, computeVectors);
  detail::requireConverged(solver.info(), what);
  GeneralEigenpairs result{solver.eigenvalues(), {}};
  if (computeVectors) result.vectors = solver.eigenvectors();
  return result;
}

Eigen::VectorXcd generalEigenvalues(const Eigen::MatrixXd& a, const std::string& what) {
  return generalEigenpairs(a, false, what).values;
}

}  // namespace mfwave
