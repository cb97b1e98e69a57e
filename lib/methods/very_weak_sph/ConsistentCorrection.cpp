#include "methods/very_weak_sph/ConsistentCorrection.hpp"

#include "core/Error.hpp"
#include "methods/very_weak_sph/QuadraticMonomials.hpp"
#include "methods/very_weak_sph/StatisticalVolume.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

namespace mfwave {
namespace {

using RowMajorMatrix = Eigen::SparseMatrix<Real, Eigen::RowMajor, int>;

// The columns of particle a's row: its physical neighbours (sorted, as in the neighbour list) and
// the facets of those neighbours (sorted too: facets are numbered in particle order).
struct Stencil {
  std::vector<Index> particle;
  std::vector<Index> facet;
};

template <int D>
Stencil stencilOf(const ParticleSet<D>& particles, const NeighbourList& neighbours, const BoundaryFacets<D>& facets,
                  Index a) {
  Stencil s;
  for (Index b : neighbours.row(a)) {
    if (b >= particles.physicalCount()) continue;  // ghosts carry no unknowns and no facets
    s.particle.push_back(b);
    for (Index f = facets.begin(b); f < facets.end(b); ++f) s.facet.push_back(f);
  }
  return s;
}

// Position of `value` in a sorted list, -1 if absent.
Index localIndex(const std::vector<Index>& sorted, Index value) {
  const auto it = std::lower_bound(sorted.begin(), sorted.end(), value);
  return (it == sorted.end() || *it != value) ? -1 : static_cast<Index>(it - sorted.begin());
}

// Where row a writes: the CSR arrays of the corrected matrices, laid out before the parallel loop.
struct Output {
  int* operatorInner;
  Real* operatorValues;
  int* tractionInner;
  Real* tractionValues;
  Index operatorBase;  // first slot of row D a (row D a + i starts i D p slots later)
  Index tractionBase;
};

// Solves particle a's D scalar rows; returns the largest relative residual (infinity when an input
// entry lies outside the stencil).
template <int D>
Real correctRow(const ParticleSet<D>& particles, const Kernel& kernel, const std::vector<Real>& volumes,
                const BoundaryFacets<D>& facets, const Material& material, const QuadraticMonomials<D>& monomials,
                const RowMajorMatrix& operator0, const RowMajorMatrix& traction0, Index a, const Stencil& s,
                const Output& out) {
  constexpr int fields = D * QuadraticMonomials<D>::count;
  const int p = static_cast<int>(s.particle.size());
  const int q = static_cast<int>(s.facet.size());
  const int unknowns = D * (p + q);
  const Real h = kernel.smoothingLength();
  const Real lambda = material.lambda(), mu = material.mu(), modulus = material.pWaveModulus();
  const Vec<D> xa = particles.position(a);

  // Dimensionless unknowns: G in units (lambda + 2 mu) / h^2, T in units 1 / h; fields
  // u = e_k m((x - x^a) / h), tractions in units (lambda + 2 mu) / h, targets in (lambda + 2 mu) / h^2.
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(fields, unknowns);
  Eigen::VectorXd sqrtWeight(unknowns);
  Eigen::MatrixXd target(fields, D);
  for (int j = 0; j < p; ++j) {
    const Index b = s.particle[static_cast<std::size_t>(j)];
    const Vec<D> r = xa - particles.position(b);
    const Vec<D> xi = -r / h;
    const Real w = std::sqrt(kernel.value(r) * volumes[static_cast<std::size_t>(b)]);  // W_ab V_b
    for (int m = 0; m < QuadraticMonomials<D>::count; ++m) {
      const Real value = monomials.value(m, xi);
      for (int k = 0; k < D; ++k) A(k * QuadraticMonomials<D>::count + m, D * j + k) = value;
    }
    for (int k = 0; k < D; ++k) sqrtWeight[D * j + k] = w;
  }
  for (int t = 0; t < q; ++t) {
    const auto f = static_cast<std::size_t>(s.facet[static_cast<std::size_t>(t)]);
    const Vec<D> r = xa - particles.position(facets.particle[f]);
    const Vec<D> xi = -r / h;
    const Vec<D>& n = facets.normal[f];
    const Real w = std::sqrt(kernel.value(r) * facets.area[f] * h);  // W_ab A_f h
    for (int m = 0; m < QuadraticMonomials<D>::count; ++m) {
      const Vec<D> g = monomials.gradient(m, xi);
      for (int k = 0; k < D; ++k)
        for (int l = 0; l < D; ++l)
          // t_l = sigma_lj n_j for u = e_k m: lambda n_l d_k m + mu (delta_lk n.grad m + n_k d_l m).
          A(k * QuadraticMonomials<D>::count + m, D * (p + t) + l) =
              (lambda * n[l] * g[k] + mu * ((l == k ? n.dot(g) : 0.0) + n[k] * g[l])) / modulus;
    }
    for (int l = 0; l < D; ++l) sqrtWeight[D * (p + t) + l] = w;
  }
  for (int m = 0; m < QuadraticMonomials<D>::count; ++m) {
    const Mat<D> hess = monomials.hessian(m);
    for (int k = 0; k < D; ++k)
      for (int i = 0; i < D; ++i)
        // div sigma_i = (lambda + mu) d_i d_k m + mu delta_ik Lap m.
        target(k * QuadraticMonomials<D>::count + m, i) =
            ((lambda + mu) * hess(i, k) + (i == k ? mu * hess.trace() : 0.0)) / modulus;
  }

  // The starting weights, dimensionless, one column per component i.
  Eigen::MatrixXd x = Eigen::MatrixXd::Zero(unknowns, D);
  for (int i = 0; i < D; ++i) {
    for (RowMajorMatrix::InnerIterator it(operator0, static_cast<int>(D * a + i)); it; ++it) {
      const Index j = localIndex(s.particle, it.col() / D);
      if (j < 0) return std::numeric_limits<Real>::infinity();
      x(D * j + it.col() % D, i) = it.value() * h * h / modulus;
    }
    for (RowMajorMatrix::InnerIterator it(traction0, static_cast<int>(D * a + i)); it; ++it) {
      const Index t = localIndex(s.facet, it.col() / D);
      if (t < 0) return std::numeric_limits<Real>::infinity();
      x(D * (p + t) + it.col() % D, i) = it.value() * h;
    }
  }

  // delta = W^{1/2} (A W^{1/2})^+ (target - A x): the minimum of sum delta^2 / W meeting A (x + delta) = target.
  const Eigen::MatrixXd scaled = A * sqrtWeight.asDiagonal();
  const Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> decomposition(scaled);
  const Eigen::MatrixXd delta = sqrtWeight.asDiagonal() * decomposition.solve(Eigen::MatrixXd(target - A * x));
  x += delta;

  // Residual relative to the size of the terms that cancel.
  const Eigen::MatrixXd error = (A * x - target).cwiseAbs();
  const Eigen::MatrixXd scale = A.cwiseAbs() * x.cwiseAbs() + target.cwiseAbs();
  Real residual = 0;
  for (int c = 0; c < fields; ++c)
    for (int i = 0; i < D; ++i) residual = std::max(residual, error(c, i) / scale(c, i));

  for (int i = 0; i < D; ++i) {
    for (int j = 0; j < p; ++j)
      for (int k = 0; k < D; ++k) {
        const auto slot = static_cast<std::size_t>(out.operatorBase + i * D * p + D * j + k);
        out.operatorInner[slot] = static_cast<int>(D * s.particle[static_cast<std::size_t>(j)] + k);
        out.operatorValues[slot] = x(D * j + k, i) * modulus / (h * h);
      }
    for (int t = 0; t < q; ++t)
      for (int l = 0; l < D; ++l) {
        const auto slot = static_cast<std::size_t>(out.tractionBase + i * D * q + D * t + l);
        out.tractionInner[slot] = static_cast<int>(D * s.facet[static_cast<std::size_t>(t)] + l);
        out.tractionValues[slot] = x(D * (p + t) + l, i) / h;
      }
  }
  return residual;
}

SparseMatrix fromRows(Index rows, Index cols, std::vector<int>& outer, std::vector<int>& inner,
                      std::vector<Real>& values) {
  const Eigen::Map<const RowMajorMatrix> rowMajor(static_cast<int>(rows), static_cast<int>(cols),
                                                  static_cast<int>(values.size()), outer.data(), inner.data(),
                                                  values.data());
  return SparseMatrix(rowMajor);
}

}  // namespace

template <int D>
ConsistencyReport correctToQuadraticConsistency(const ParticleSet<D>& particles, const NeighbourList& neighbours,
                                                const Kernel& kernel, const std::vector<Real>& volumes,
                                                const BoundaryFacets<D>& facets, const Material& material,
                                                SparseMatrix& operatorMatrix, SparseMatrix& tractionMatrix,
                                                Real tolerance) {
  checkVeryWeakInputs(particles, neighbours, kernel);
  const Index n = particles.physicalCount();
  if (static_cast<Index>(volumes.size()) != n) throw InputError("volumes", "need one volume per physical particle");
  if (static_cast<Index>(facets.offsets.size()) != n + 1 || facets.area.size() != facets.particle.size() ||
      facets.normal.size() != facets.particle.size())
    throw InputError("facets", "the facets do not belong to this particle set");
  if (operatorMatrix.rows() != D * n || operatorMatrix.cols() != D * n || tractionMatrix.rows() != D * n ||
      tractionMatrix.cols() != D * facets.count())
    throw InputError("operator", "the operator or traction matrix does not match the particles and facets");

  const RowMajorMatrix operator0(operatorMatrix);
  const RowMajorMatrix traction0(tractionMatrix);

  // Layout: particle a's D rows hold D p_a operator entries and D q_a traction entries each.
  std::vector<Stencil> stencils(static_cast<std::size_t>(n));
  std::vector<Index> operatorStart(static_cast<std::size_t>(n) + 1, 0), tractionStart(static_cast<std::size_t>(n) + 1, 0);
  for (Index a = 0; a < n; ++a) {
    const auto ai = static_cast<std::size_t>(a);
    stencils[ai] = stencilOf(particles, neighbours, facets, a);
    operatorStart[ai + 1] = operatorStart[ai] + static_cast<Index>(stencils[ai].particle.size());
    tractionStart[ai + 1] = tractionStart[ai] + static_cast<Index>(stencils[ai].facet.size());
  }
  std::vector<int> operatorOuter(static_cast<std::size_t>(D * n) + 1), tractionOuter(static_cast<std::size_t>(D * n) + 1);
  for (Index a = 0; a < n; ++a)
    for (int i = 0; i < D; ++i) {
      const auto ai = static_cast<std::size_t>(a);
      const auto row = static_cast<std::size_t>(D * a + i);
      operatorOuter[row] = static_cast<int>(D * D * operatorStart[ai] + i * D * (operatorStart[ai + 1] - operatorStart[ai]));
      tractionOuter[row] = static_cast<int>(D * D * tractionStart[ai] + i * D * (tractionStart[ai + 1] - tractionStart[ai]));
    }
  operatorOuter.back() = static_cast<int>(D * D * operatorStart.back());
  tractionOuter.back() = static_cast<int>(D * D * tractionStart.back());
  std::vector<int> operatorInner(static_cast<std::size_t>(operatorOuter.back()));
  std::vector<Real> operatorValues(operatorInner.size());
  std::vector<int> tractionInner(static_cast<std::size_t>(tractionOuter.back()));
  std::vector<Real> tractionValues(tractionInner.size());

  const QuadraticMonomials<D> monomials;
  std::vector<Real> residuals(static_cast<std::size_t>(n), 0);
#pragma omp parallel for schedule(dynamic, 16)
  for (Index a = 0; a < n; ++a) {
    const auto ai = static_cast<std::size_t>(a);
    const Output out{operatorInner.data(), operatorValues.data(), tractionInner.data(), tractionValues.data(),
                     D * D * operatorStart[ai], D * D * tractionStart[ai]};
    residuals[ai] = correctRow(particles, kernel, volumes, facets, material, monomials, operator0, traction0, a,
                               stencils[ai], out);
  }

  ConsistencyReport report;
  report.rowsSolved = n;
  for (Index a = 0; a < n; ++a) {
    const Real residual = residuals[static_cast<std::size_t>(a)];
    if (!(residual <= tolerance)) {
      std::ostringstream message;
      message << "consistent correction: the row of particle " << a << " at (" << particles.position(a).transpose()
              << ") "
              << (std::isinf(residual) ? std::string("has input weights outside its kernel support")
                                       : "cannot reproduce the quadratic fields (relative residual " +
                                             std::to_string(residual) + ")");
      throw Error(message.str());
    }
    report.residual = std::max(report.residual, residual);
  }
  operatorMatrix = fromRows(D * n, D * n, operatorOuter, operatorInner, operatorValues);
  tractionMatrix = fromRows(D * n, D * facets.count(), tractionOuter, tractionInner, tractionValues);
  return report;
}

#define MFWAVE_INSTANTIATE(D)                                                                                      \
  template ConsistencyReport correctToQuadraticConsistency<D>(const ParticleSet<D>&, const NeighbourList&,          \
                                                              const Kernel&, const std::vector<Real>&,             \
                                                              const BoundaryFacets<D>&, const Material&,           \
                                                              SparseMatrix&, SparseMatrix&, Real);
MFWAVE_INSTANTIATE(1)
MFWAVE_INSTANTIATE(2)
MFWAVE_INSTANTIATE(3)
#undef MFWAVE_INSTANTIATE

}  // namespace mfwave
