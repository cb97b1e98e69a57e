#include "methods/very_weak_sph/ConsistentCorrection.hpp"

#include "core/Error.hpp"
#include "methods/very_weak_sph/QuadraticMonomials.hpp"
#include "methods/very_weak_sph/RowTypes.hpp"
#include "methods/very_weak_sph/StatisticalVolume.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cstdint>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

namespace mfwave {
namespace {

using RowMajorMatrix = Eigen::SparseMatrix<Real, Eigen::RowMajor, int>;

// Row keys round the inputs (offsets in units of h, dimensionless volumes, areas and weights) to
// 1e-9: far above the round-off by which translated lattice rows differ (~1e-14), far below any
// difference between rows that are not translates (a moved particle, a different boundary).
constexpr Real rowKeyQuantum = 1e-9;

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

// The starting weights of particle a's D scalar rows, dimensionless (G in units (lambda + 2 mu) / h^2,
// T in units 1 / h), one column per component i; false when an entry lies outside the stencil.
template <int D>
bool startingWeights(const RowMajorMatrix& operator0, const RowMajorMatrix& traction0, Index a, const Stencil& s,
                     Real h, Real modulus, Eigen::MatrixXd& x) {
  const int p = static_cast<int>(s.particle.size());
  x = Eigen::MatrixXd::Zero(D * (p + static_cast<int>(s.facet.size())), D);
  for (int i = 0; i < D; ++i) {
    for (RowMajorMatrix::InnerIterator it(operator0, static_cast<int>(D * a + i)); it; ++it) {
      const Index j = localIndex(s.particle, it.col() / D);
      if (j < 0) return false;
      x(D * j + it.col() % D, i) = it.value() * h * h / modulus;
    }
    for (RowMajorMatrix::InnerIterator it(traction0, static_cast<int>(D * a + i)); it; ++it) {
      const Index t = localIndex(s.facet, it.col() / D);
      if (t < 0) return false;
      x(D * (p + t) + it.col() % D, i) = it.value() * h;
    }
  }
  return true;
}

// Everything particle a's solve depends on besides the global kernel and material, in units of h:
// neighbour offsets and volumes, facet offsets, normals and areas, and the starting weights x.
// Rows with equal keys have equal constraint matrices, weights and right-hand sides up to round-off.
template <int D>
void rowKey(const ParticleSet<D>& particles, const std::vector<Real>& volumes, const BoundaryFacets<D>& facets,
            Real h, Index a, const Stencil& s, const Eigen::MatrixXd& x, RowKey& key) {
  key.clear();
  key.addCount(static_cast<Index>(s.particle.size()));
  key.addCount(static_cast<Index>(s.facet.size()));
  const Vec<D> xa = particles.position(a);
  const Real volumeUnit = std::pow(h, D), areaUnit = std::pow(h, D - 1);
  for (Index b : s.particle) {
    const Vec<D> offset = (particles.position(b) - xa) / h;
    for (int k = 0; k < D; ++k) key.add(offset[k]);
    key.add(volumes[static_cast<std::size_t>(b)] / volumeUnit);
  }
  for (Index facet : s.facet) {
    const auto f = static_cast<std::size_t>(facet);
    const Vec<D> offset = (particles.position(facets.particle[f]) - xa) / h;
    for (int k = 0; k < D; ++k) key.add(offset[k]);
    for (int k = 0; k < D; ++k) key.add(facets.normal[f][k]);
    key.add(facets.area[f] / areaUnit);
  }
  for (Eigen::Index j = 0; j < x.size(); ++j) key.add(x.data()[j]);
}

// div sigma_i of the fields u = e_k m((x - x^a) / h) at x^a, in units (lambda + 2 mu) / h^2: the
// same for every row.
template <int D>
Eigen::MatrixXd quadraticTargets(const Material& material, const QuadraticMonomials<D>& monomials) {
  const Real lambda = material.lambda(), mu = material.mu(), modulus = material.pWaveModulus();
  Eigen::MatrixXd target(D * QuadraticMonomials<D>::count, D);
  for (int m = 0; m < QuadraticMonomials<D>::count; ++m) {
    const Mat<D> hess = monomials.hessian(m);
    for (int k = 0; k < D; ++k)
      for (int i = 0; i < D; ++i)
        // div sigma_i = (lambda + mu) d_i d_k m + mu delta_ik Lap m.
        target(k * QuadraticMonomials<D>::count + m, i) =
            ((lambda + mu) * hess(i, k) + (i == k ? mu * hess.trace() : 0.0)) / modulus;
  }
  return target;
}

// Particle a's local problem: constraints A, square roots of the kernel weights, starting weights x.
struct LocalRow {
  Eigen::MatrixXd A;
  Eigen::VectorXd sqrtWeight;
  Eigen::MatrixXd x;
};

// False when an input entry lies outside the stencil.
template <int D>
bool buildRow(const ParticleSet<D>& particles, const Kernel& kernel, const std::vector<Real>& volumes,
              const BoundaryFacets<D>& facets, const Material& material, const QuadraticMonomials<D>& monomials,
              const RowMajorMatrix& operator0, const RowMajorMatrix& traction0, Index a, const Stencil& s,
              LocalRow& row) {
  constexpr int fields = D * QuadraticMonomials<D>::count;
  const int p = static_cast<int>(s.particle.size());
  const int q = static_cast<int>(s.facet.size());
  const int unknowns = D * (p + q);
  const Real h = kernel.smoothingLength();
  const Real lambda = material.lambda(), mu = material.mu(), modulus = material.pWaveModulus();
  const Vec<D> xa = particles.position(a);

  // Dimensionless unknowns: G in units (lambda + 2 mu) / h^2, T in units 1 / h; fields
  // u = e_k m((x - x^a) / h), tractions in units (lambda + 2 mu) / h, targets in (lambda + 2 mu) / h^2.
  Eigen::MatrixXd& A = row.A;
  A = Eigen::MatrixXd::Zero(fields, unknowns);
  row.sqrtWeight.resize(unknowns);
  for (int j = 0; j < p; ++j) {
    const Index b = s.particle[static_cast<std::size_t>(j)];
    const Vec<D> r = xa - particles.position(b);
    const Vec<D> xi = -r / h;
    const Real w = std::sqrt(kernel.value(r) * volumes[static_cast<std::size_t>(b)]);  // W_ab V_b
    for (int m = 0; m < QuadraticMonomials<D>::count; ++m) {
      const Real value = monomials.value(m, xi);
      for (int k = 0; k < D; ++k) A(k * QuadraticMonomials<D>::count + m, D * j + k) = value;
    }
    for (int k = 0; k < D; ++k) row.sqrtWeight[D * j + k] = w;
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
    for (int l = 0; l < D; ++l) row.sqrtWeight[D * (p + t) + l] = w;
  }
  return startingWeights<D>(operator0, traction0, a, s, h, modulus, row.x);
}

// delta = W^{1/2} (A W^{1/2})^+ (target - A x): the minimum of sum delta^2 / W meeting A (x + delta) = target.
Eigen::MatrixXd correctionOf(const LocalRow& row, const Eigen::MatrixXd& target) {
  const Eigen::MatrixXd scaled = row.A * row.sqrtWeight.asDiagonal();
  const Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> decomposition(scaled);
  return row.sqrtWeight.asDiagonal() * decomposition.solve(Eigen::MatrixXd(target - row.A * row.x));
}

// Applies the correction, writes particle a's D rows and returns the largest relative residual.
template <int D>
Real finishRow(LocalRow& row, const Eigen::MatrixXd& delta, const Eigen::MatrixXd& target, Real h, Real modulus,
               const Stencil& s, const Output& out) {
  const int p = static_cast<int>(s.particle.size());
  const int q = static_cast<int>(s.facet.size());
  Eigen::MatrixXd& x = row.x;
  x += delta;

  // Residual relative to the size of the terms that cancel.
  const Eigen::MatrixXd error = (row.A * x - target).cwiseAbs();
  const Eigen::MatrixXd scale = row.A.cwiseAbs() * x.cwiseAbs() + target.cwiseAbs();
  Real residual = 0;
  for (Eigen::Index c = 0; c < target.rows(); ++c)
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

void release(std::vector<int>& outer, std::vector<int>& inner, std::vector<Real>& values) {
  std::vector<int>().swap(outer);
  std::vector<int>().swap(inner);
  std::vector<Real>().swap(values);
}

}  // namespace

template <int D>
ConsistencyReport correctToQuadraticConsistency(const ParticleSet<D>& particles, const NeighbourList& neighbours,
                                                const Kernel& kernel, const std::vector<Real>& volumes,
                                                const BoundaryFacets<D>& facets, const Material& material,
                                                SparseMatrix& operatorMatrix, SparseMatrix& tractionMatrix,
                                                bool reuseRowTypes, Real tolerance) {
  checkVeryWeakInputs(particles, neighbours, kernel);
  const Index n = particles.physicalCount();
  if (static_cast<Index>(volumes.size()) != n) throw InputError("volumes", "need one volume per physical particle");
  if (static_cast<Index>(facets.offsets.size()) != n + 1 || facets.area.size() != facets.particle.size() ||
      facets.normal.size() != facets.particle.size())
    throw InputError("facets", "the facets do not belong to this particle set");
  if (operatorMatrix.rows() != D * n || operatorMatrix.cols() != D * n || tractionMatrix.rows() != D * n ||
      tractionMatrix.cols() != D * facets.count())
    throw InputError("operator", "the operator or traction matrix does not match the particles and facets");

  // The inputs by rows; the column-major originals are released at once (swap: assigning an empty
  // Eigen 3.4 sparse matrix keeps the allocation), so that K is held at most twice at any time.
  RowMajorMatrix operator0(operatorMatrix);
  SparseMatrix().swap(operatorMatrix);
  RowMajorMatrix traction0(tractionMatrix);
  SparseMatrix().swap(tractionMatrix);

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
  const Eigen::MatrixXd target = quadraticTargets<D>(material, monomials);
  const Real h = kernel.smoothingLength(), modulus = material.pWaveModulus();
  const auto output = [&](Index a) {
    const auto ai = static_cast<std::size_t>(a);
    return Output{operatorInner.data(), operatorValues.data(), tractionInner.data(), tractionValues.data(),
                  D * D * operatorStart[ai], D * D * tractionStart[ai]};
  };

  // Row types (RowTypes.hpp): a representative per key, by hash; without reuse every row is its own.
  std::vector<Index> representative(static_cast<std::size_t>(n));
  for (Index a = 0; a < n; ++a) representative[static_cast<std::size_t>(a)] = a;
  if (reuseRowTypes) {
    std::vector<std::uint64_t> hash(static_cast<std::size_t>(n));
    std::vector<char> keyed(static_cast<std::size_t>(n));
#pragma omp parallel
    {
      RowKey key(rowKeyQuantum);
      Eigen::MatrixXd x;
#pragma omp for schedule(static)
      for (Index a = 0; a < n; ++a) {
        const auto ai = static_cast<std::size_t>(a);
        key.clear();
        if (startingWeights<D>(operator0, traction0, a, stencils[ai], h, modulus, x))
          rowKey(particles, volumes, facets, h, a, stencils[ai], x, key);
        else
          key.invalidate();
        keyed[ai] = key.valid();
        hash[ai] = key.hash();
      }
    }
    representative = representativesByHash(hash, keyed);
  }
  // Representatives that others reuse get a slot for their correction and key.
  std::vector<Index> slot(static_cast<std::size_t>(n), -1);
  Index slots = 0;
  for (Index a = 0; a < n; ++a) {
    const auto r = static_cast<std::size_t>(representative[static_cast<std::size_t>(a)]);
    if (static_cast<Index>(r) != a && slot[r] < 0) slot[r] = slots++;
  }
  std::vector<Eigen::MatrixXd> sharedDelta(static_cast<std::size_t>(slots));
  std::vector<RowKey> sharedKey(static_cast<std::size_t>(slots), RowKey(rowKeyQuantum));
  for (RowKey& key : sharedKey) key.invalidate();  // until its representative has been solved

  std::vector<Real> residuals(static_cast<std::size_t>(n), std::numeric_limits<Real>::infinity());
  std::vector<char> decomposed(static_cast<std::size_t>(n), 0);
  // Pass 1: the representatives (every row without reuse), each with its own decomposition.
#pragma omp parallel for schedule(dynamic, 16)
  for (Index a = 0; a < n; ++a) {
    const auto ai = static_cast<std::size_t>(a);
    if (representative[ai] != a) continue;
    LocalRow row;
    if (!buildRow(particles, kernel, volumes, facets, material, monomials, operator0, traction0, a, stencils[ai], row))
      continue;  // residual stays infinite: input weights outside the support
    const Eigen::MatrixXd delta = correctionOf(row, target);
    decomposed[ai] = 1;
    if (slot[ai] >= 0) {
      const auto k = static_cast<std::size_t>(slot[ai]);
      rowKey(particles, volumes, facets, h, a, stencils[ai], row.x, sharedKey[k]);
      sharedDelta[k] = delta;
    }
    residuals[ai] = finishRow<D>(row, delta, target, h, modulus, stencils[ai], output(a));
  }
  // Pass 2: the other rows take their representative's correction once their keys are seen to be
  // equal (equal hashes alone are no proof); the residual is still each row's own.
#pragma omp parallel
  {
    RowKey key(rowKeyQuantum);
#pragma omp for schedule(dynamic, 16)
    for (Index a = 0; a < n; ++a) {
      const auto ai = static_cast<std::size_t>(a);
      const auto r = static_cast<std::size_t>(representative[ai]);
      if (static_cast<Index>(r) == a) continue;
      LocalRow row;
      if (!buildRow(particles, kernel, volumes, facets, material, monomials, operator0, traction0, a, stencils[ai],
                    row))
        continue;
      rowKey(particles, volumes, facets, h, a, stencils[ai], row.x, key);
      const auto k = static_cast<std::size_t>(slot[r]);
      const bool same = key == sharedKey[k];
      const Eigen::MatrixXd delta = same ? sharedDelta[k] : correctionOf(row, target);
      decomposed[ai] = same ? 0 : 1;
      residuals[ai] = finishRow<D>(row, delta, target, h, modulus, stencils[ai], output(a));
    }
  }

  ConsistencyReport report;
  report.rowsSolved = n;
  for (char d : decomposed) report.decompositions += d;
  for (Index a = 0; a < n; ++a) {
    const Real residual = residuals[static_cast<std::size_t>(a)];
    if (!(residual <= tolerance)) {
      std::ostringstream message;
      message << "consistent correction: the row of particle " << a << " at (" << particles.position(a).transpose()
              << ") "
              << (std::isinf(residual) ? std::string("has input weights outside its kernel support")
                                       : "cannot reproduce the quadratic fields (relative residual " +
                                             std::to_string(residual) + ")");
      // Bad input, not a defect: the support holds too few neighbours for the correction's moments.
      if (!std::isinf(residual))
        throw InputError("method.smoothing_length_ratio",
                         message.str() + ": too few neighbours in the support for the quadratic correction at this "
                                         "h / dx; use a larger ratio (1.0 or more)");
      throw Error(message.str());
    }
    report.residual = std::max(report.residual, residual);
  }
  RowMajorMatrix().swap(operator0);
  RowMajorMatrix().swap(traction0);
  // Swaps, not assignments: Eigen 3.4 sparse matrices have no move assignment, an assignment copies.
  fromRows(D * n, D * n, operatorOuter, operatorInner, operatorValues).swap(operatorMatrix);
  release(operatorOuter, operatorInner, operatorValues);
  fromRows(D * n, D * facets.count(), tractionOuter, tractionInner, tractionValues).swap(tractionMatrix);
  return report;
}

#define MFWAVE_INSTANTIATE(D)                                                                                      \
  template ConsistencyReport correctToQuadraticConsistency<D>(const ParticleSet<D>&, const NeighbourList&,          \
                                                              const Kernel&, const std::vector<Real>&,             \
                                                              const BoundaryFacets<D>&, const Material&,           \
                                                              SparseMatrix&, SparseMatrix&, bool, Real);
MFWAVE_INSTANTIATE(1)
MFWAVE_INSTANTIATE(2)
MFWAVE_INSTANTIATE(3)
#undef MFWAVE_INSTANTIATE

}  // namespace mfwave
