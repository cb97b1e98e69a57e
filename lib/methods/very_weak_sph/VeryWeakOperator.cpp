#include "methods/very_weak_sph/VeryWeakOperator.hpp"

#include "core/Error.hpp"
#include "methods/very_weak_sph/StatisticalVolume.hpp"

namespace mfwave {

template <int D>
SparseMatrix assembleVeryWeakOperator(const ParticleSet<D>& particles, const NeighbourList& neighbours,
                                      const Kernel& kernel, Real lambda, Real mu, const std::vector<Real>& volumes,
                                      const BoundaryFacets<D>& facets, bool boundaryIntegral) {
  checkVeryWeakInputs(particles, neighbours, kernel);
  const Index n = particles.physicalCount();
  if (static_cast<Index>(volumes.size()) != n) throw InputError("volumes", "need one volume per physical particle");
  if (static_cast<Index>(facets.offsets.size()) != n + 1)
    throw InputError("facets", "the facets do not belong to this particle set");

  // CSR layout: particle a has p_a physical neighbours, so each of its D rows holds D p_a entries.
  std::vector<Index> start(static_cast<std::size_t>(n) + 1, 0);
  for (Index a = 0; a < n; ++a) {
    Index p = 0;
    for (Index b : neighbours.row(a)) p += b < n ? 1 : 0;
    start[static_cast<std::size_t>(a) + 1] = start[static_cast<std::size_t>(a)] + p;
  }
  const Index dofs = D * n;
  const Index nonZeros = D * D * start.back();
  std::vector<int> outer(static_cast<std::size_t>(dofs) + 1);
  std::vector<int> inner(static_cast<std::size_t>(nonZeros));
  std::vector<Real> values(static_cast<std::size_t>(nonZeros));

#pragma omp parallel for schedule(dynamic, 64)
  for (Index a = 0; a < n; ++a) {
    const Index p = start[static_cast<std::size_t>(a) + 1] - start[static_cast<std::size_t>(a)];
    const Index base = D * D * start[static_cast<std::size_t>(a)];
    for (int i = 0; i < D; ++i) outer[static_cast<std::size_t>(D * a + i)] = static_cast<int>(base + i * D * p);
    if (a == n - 1) outer[static_cast<std::size_t>(dofs)] = static_cast<int>(nonZeros);
    const Vec<D> xa = particles.position(a);
    Index column = 0;  // position of b among a's physical neighbours
    for (Index b : neighbours.row(a)) {
      if (b >= n) continue;
      const Vec<D> r = xa - particles.position(b);
      // Ding-Long-Wu eq. (21): K_ik(x^a - x^b) V_b, every neighbour b including a itself.
      Mat<D> block = veryWeakInteriorBlock<D>(kernel, lambda, mu, r) * volumes[static_cast<std::size_t>(b)];
      // Ding-Long-Wu eq. (22): Gamma_ik(x^a - x^b; n_b) A_b for each facet of a boundary neighbour b.
      if (boundaryIntegral) {
        for (Index f = facets.begin(b); f < facets.end(b); ++f)
          block += veryWeakBoundaryBlock<D>(kernel, lambda, mu, r, facets.normal[static_cast<std::size_t>(f)]) *
                   facets.area[static_cast<std::size_t>(f)];
      }
      for (int i = 0; i < D; ++i) {
        const Index slot = base + i * D * p + D * column;
        for (int k = 0; k < D; ++k) {
          inner[static_cast<std::size_t>(slot + k)] = static_cast<int>(D * b + k);
          values[static_cast<std::size_t>(slot + k)] = block(i, k);
        }
      }
      ++column;
    }
  }
  if (n == 0) outer[0] = 0;
  const Eigen::Map<const Eigen::SparseMatrix<Real, Eigen::RowMajor, int>> rowMajor(
      static_cast<int>(dofs), static_cast<int>(dofs), static_cast<int>(nonZeros), outer.data(), inner.data(),
      values.data());
  return SparseMatrix(rowMajor);
}

template SparseMatrix assembleVeryWeakOperator<1>(const ParticleSet<1>&, const NeighbourList&, const Kernel&, Real, Real,
                                                  const std::vector<Real>&, const BoundaryFacets<1>&, bool);
template SparseMatrix assembleVeryWeakOperator<2>(const ParticleSet<2>&, const NeighbourList&, const Kernel&, Real, Real,
                                                  const std::vector<Real>&, const BoundaryFacets<2>&, bool);
template SparseMatrix assembleVeryWeakOperator<3>(const ParticleSet<3>&, const NeighbourList&, const Kernel&, Real, Real,
                                                  const std::vector<Real>&, const BoundaryFacets<3>&, bool);

}  // namespace mfwave
