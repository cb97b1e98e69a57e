#pragma once
// Dense eigenvalue problems: the exact spectra of small operators (lattice symbols, rest
// operators, Ritz projections, the test problems' reference solutions).
//
// Why these are functions and not Eigen's solver classes at the call site: each Eigen eigensolver
// instantiated in a file costs that file 10-30 s of compilation (three times that in the sanitize
// build), and a dozen files used them. Here each solver is instantiated once, in
// DenseEigenproblems.cpp. Every function throws mfwave::Error naming `what` if the solver does not
// converge.

#include "core/Types.hpp"

#include <Eigen/Core>

#include <string>

namespace mfwave {

// A real symmetric matrix: eigenvalues ascending, orthonormal eigenvectors in the columns.
// Only the lower triangle of `a` is read.
struct SymmetricEigenpairs {
  Eigen::VectorXd values;
  Eigen::MatrixXd vectors;
};
SymmetricEigenpairs symmetricEigenpairs(const Eigen::MatrixXd& a, const std::string& what = "symmetricEigenpairs");
Eigen::VectorXd symmetricEigenvalues(const Eigen::MatrixXd& a, const std::string& what = "symmetricEigenvalues");

// A complex Hermitian matrix: real eigenvalues ascending, orthonormal eigenvectors. Only the lower
// triangle of `a` is read.
struct HermitianEigenpairs {
  Eigen::VectorXd values;
  Eigen::MatrixXcd vectors;
};
HermitianEigenpairs hermitianEigenpairs(const Eigen::MatrixXcd& a, const std::string& what = "hermitianEigenpairs");
Eigen::VectorXd hermitianEigenvalues(const Eigen::MatrixXcd& a, const std::string& what = "hermitianEigenvalues");

// A general square matrix, real or complex: eigenvalues in the solver's order (not sorted) and,
// when asked for, the right eigenvectors in the columns (normalised; `vectors` is empty otherwise).
struct GeneralEigenpairs {
  Eigen::VectorXcd values;
  Eigen::MatrixXcd vectors;
};
GeneralEigenpairs generalEigenpairs(const Eigen::MatrixXd& a, bool computeVectors,
                                    const std::string& what = "generalEigenpairs");
GeneralEigenpairs generalEigenpairs(const Eigen::MatrixXcd& a, bool computeVectors,
                                    const std::string& what = "generalEigenpairs");
Eigen::VectorXcd generalEigenvalues(const Eigen::MatrixXd& a, const std::string& what = "generalEigenvalues");

namespace detail {
// Throws mfwave::Error "<what>: the dense eigenvalue solver did not converge" unless `info` is Success.
void requireConverged(Eigen::ComputationInfo info, const std::string& what);
}  // namespace detail

}  // namespace mfwave
