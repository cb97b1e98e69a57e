#include "numerics/RestModes.hpp"

#include "core/Error.hpp"
#include "solvers/DenseEigenproblems.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <string>

namespace mfwave {

Eigen::MatrixXd restOperator(SplitFirstOrderSystem& system, Real t, const Vector& restState,
                             const std::vector<Index>& velocityEntries, Real relativePerturbation) {
  std::vector<Index> rows(velocityEntries.size());
  for (std::size_t r = 0; r < rows.size(); ++r) rows[r] = static_cast<Index>(r);
  return restOperatorRows(system, t, restState, velocityEntries, rows, relativePerturbation);
}

namespace {

void requireRows(const std::vector<Index>& rows, Index m) {
  for (Index r : rows)
    if (r < 0 || r >= m) throw InputError("rows", "row " + std::to_string(r) + " is not in [0, " + std::to_string(m) + ")");
}

// The unit directions e_k for k in `columns` (m x columns.size()).
SparseMatrix unitDirections(const std::vector<Index>& columns, Index m) {
  std::vector<Eigen::Triplet<Real>> ones;
  for (std::size_t j = 0; j < columns.size(); ++j)
    ones.emplace_back(static_cast<int>(columns[j]), static_cast<int>(j), 1.0);
  SparseMatrix directions(static_cast<int>(m), static_cast<int>(columns.size()));
  directions.setFromTriplets(ones.begin(), ones.end());
  return directions;
}

std::vector<Index> allIndices(Index m) {
  std::vector<Index> all(static_cast<std::size_t>(m));
  for (Index k = 0; k < m; ++k) all[static_cast<std::size_t>(k)] = k;
  return all;
}

}  // namespace

Eigen::MatrixXd restOperatorRows(SplitFirstOrderSystem& system, Real t, const Vector& restState,
                                 const std::vector<Index>& velocityEntries, const std::vector<Index>& rows,
                                 Real relativePerturbation) {
  const auto m = static_cast<Index>(velocityEntries.size());
  requireRows(rows, m);
  return restOperatorProducts(system, t, restState, velocityEntries, unitDirections(allIndices(m), m), rows,
                              relativePerturbation);
}

Eigen::MatrixXd restOperatorColumns(SplitFirstOrderSystem& system, Real t, const Vector& restState,
                                    const std::vector<Index>& velocityEntries, const std::vector<Index>& columns,
                                    Real relativePerturbation) {
  const auto m = static_cast<Index>(velocityEntries.size());
  for (Index k : columns)
    if (k < 0 || k >= m)
      throw InputError("columns", "column " + std::to_string(k) + " is not in [0, " + std::to_string(m) + ")");
  return restOperatorProducts(system, t, restState, velocityEntries, unitDirections(columns, m), allIndices(m),
                              relativePerturbation);
}

// A d_j for each direction d_j: dQ/dv d_j exactly (Q being linear in v at rest), then dP_v/dq
// times it by a central difference of step eps dq.
Eigen::MatrixXd restOperatorProducts(SplitFirstOrderSystem& system, Real t, const Vector& restState,
                                     const std::vector<Index>& velocityEntries, const SparseMatrix& directions,
                                     const std::vector<Index>& rows, Real relativePerturbation) {
  const Index n = system.size();
  const Index nq = system.configurationSize();
  if (restState.size() != n)
    throw InputError("state", "has " + std::to_string(restState.size()) + " entries, the system " + std::to_string(n));
  for (Index k : velocityEntries)
    if (k < nq || k >= n) throw InputError("velocityEntries", "entry " + std::to_string(k) + " is not in p");
  if (!(relativePerturbation > 0)) throw InputError("relativePerturbation", "must be positive");
  const auto m = static_cast<Index>(velocityEntries.size());
  if (directions.rows() != m)
    throw InputError("directions", "has " + std::to_string(directions.rows()) + " rows, one per velocity entry (" +
                                       std::to_string(m) + ") needed");
  requireRows(rows, m);
  const Real scale = std::max<Real>(1, restState.head(nq).cwiseAbs().maxCoeff());

  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(static_cast<Index>(rows.size()), directions.cols());
  Vector qdotRest(nq), qdot(nq), pPlus(n - nq), pMinus(n - nq);
  system.configurationRate(t, restState, qdotRest);
  Vector y = restState;
  for (Index j = 0; j < directions.cols(); ++j) {
    y = restState;
    for (SparseMatrix::InnerIterator it(directions, static_cast<int>(j)); it; ++it)
      y[velocityEntries[static_cast<std::size_t>(it.row())]] += it.value();
    system.configurationRate(t, y, qdot);
    const Vector dq = qdot - qdotRest;
    const Real size = dq.cwiseAbs().maxCoeff();
    if (size == 0) continue;  // a zero column
    const Real eps = relativePerturbation * scale / size;
    y = restState;
    y.head(nq) += eps * dq;
    system.momentumRate(t, y, pPlus);
    y.head(nq) = restState.head(nq) - eps * dq;
    system.momentumRate(t, y, pMinus);
    for (std::size_t r = 0; r < rows.size(); ++r) {
      const Index entry = velocityEntries[static_cast<std::size_t>(rows[r])] - nq;
      A(static_cast<Index>(r), j) = (pPlus[entry] - pMinus[entry]) / (2 * eps);
    }
  }
  return A;
}

RestModes restModes(const Eigen::MatrixXd& restOperator, Real zeroTolerance) {
  RestModes modes;
  if (restOperator.rows() == 0) return modes;
  const Eigen::VectorXcd lambda = generalEigenvalues(restOperator, "restModes");
  const Real largest = lambda.cwiseAbs().maxCoeff();
  for (Index k = 0; k < lambda.size(); ++k) {
    const std::complex<Real> l = lambda[k];
    if (std::abs(l) <= zeroTolerance * largest) {
      ++modes.zeroModes;
      continue;
    }
    // v'' = lambda v: v ~ exp(s t) with s^2 = lambda; growth is Re s of the root with Re s >= 0.
    const Real growth = std::abs(std::sqrt(l).real());
    if (std::abs(l.imag()) > zeroTolerance * largest || l.real() > 0)
      modes.largestGrowthRate = std::max(modes.largestGrowthRate, growth);
    if (l.real() < 0) modes.frequencies.push_back(std::sqrt(-l.real()));
  }
  std::sort(modes.frequencies.begin(), modes.frequencies.end());
  return modes;
}

}  // namespace mfwave
