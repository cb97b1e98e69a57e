#include "methods/very_weak_sph/TractionLoad.hpp"

#include "core/Error.hpp"
#include "methods/very_weak_sph/StatisticalVolume.hpp"

namespace mfwave {

template <int D>
SparseMatrix assembleTractionMatrix(const ParticleSet<D>& particles, const NeighbourList& neighbours,
                                    const Kernel& kernel, const BoundaryFacets<D>& facets) {
  checkVeryWeakInputs(particles, neighbours, kernel);
  const Index n = particles.physicalCount();
  if (static_cast<Index>(facets.offsets.size()) != n + 1)
    throw InputError("facets", "the facets do not belong to this particle set");
  // Per particle a, the facets of its physical boundary neighbours (rows are sorted by b, so the
  // columns come out sorted): each of a's D rows holds that many entries (block W A I is diagonal).
  std::vector<Index> start(static_cast<std::size_t>(n) + 1, 0);
  for (Index a = 0; a < n; ++a) {
    Index count = 0;
    for (Index b : neighbours.row(a))
      if (b < n) count += facets.end(b) - facets.begin(b);
    start[static_cast<std::size_t>(a) + 1] = start[static_cast<std::size_t>(a)] + count;
  }
  const Index rows = D * n;
  const Index nonZeros = D * start.back();
  std::vector<int> outer(static_cast<std::size_t>(rows) + 1, 0);
  std::vector<int> inner(static_cast<std::size_t>(nonZeros));
  std::vector<Real> values(static_cast<std::size_t>(nonZeros));
  for (Index a = 0; a < n; ++a) {
    const Index count = start[static_cast<std::size_t>(a) + 1] - start[static_cast<std::size_t>(a)];
    for (int i = 0; i < D; ++i)
      outer[static_cast<std::size_t>(D * a + i)] = static_cast<int>(D * start[static_cast<std::size_t>(a)] + i * count);
  }
  outer[static_cast<std::size_t>(rows)] = static_cast<int>(nonZeros);

#pragma omp parallel for schedule(dynamic, 64)
  for (Index a = 0; a < n; ++a) {
    const Vec<D> xa = particles.position(a);
    Index slot = 0;
    for (Index b : neighbours.row(a)) {
      if (b >= n) continue;
      const Real w = kernel.value(Vec<D>(xa - particles.position(b)));
      for (Index f = facets.begin(b); f < facets.end(b); ++f) {
        // Ding-Long-Wu eq. (19): W_ab A_b T_i(x^b).
        const Real weight = w * facets.area[static_cast<std::size_t>(f)];
        for (int i = 0; i < D; ++i) {
          const auto s = static_cast<std::size_t>(outer[static_cast<std::size_t>(D * a + i)] + slot);
          inner[s] = static_cast<int>(D * f + i);
          values[s] = weight;
        }
        ++slot;
      }
    }
  }
  const Eigen::Map<const Eigen::SparseMatrix<Real, Eigen::RowMajor, int>> rowMajor(
      static_cast<int>(rows), static_cast<int>(D * facets.count()), static_cast<int>(nonZeros), outer.data(),
      inner.data(), values.data());
  return SparseMatrix(rowMajor);
}

template <int D>
Vector facetTractionsFromNodal(const BoundaryFacets<D>& facets, const Vector& nodalTraction) {
  const Index n = static_cast<Index>(facets.offsets.size()) - 1;
  if (nodalTraction.size() != D * n) throw InputError("traction", "need D components per physical particle");
  Vector t(D * facets.count());
  for (Index f = 0; f < facets.count(); ++f)
    t.template segment<D>(D * f) = nodalTraction.template segment<D>(D * facets.particle[static_cast<std::size_t>(f)]);
  return t;
}

template <int D>
Vector facetTractionsFromStress(const BoundaryFacets<D>& facets, const Mat<D>& stress) {
  Vector t(D * facets.count());
  for (Index f = 0; f < facets.count(); ++f)
    t.template segment<D>(D * f) = stress * facets.normal[static_cast<std::size_t>(f)];
  return t;
}

void addTractionLoad(const SparseMatrix& tractionMatrix, const Vector& facetTractions, Vector& f) {
  if (facetTractions.size() != tractionMatrix.cols() || f.size() != tractionMatrix.rows())
    throw InputError("traction", "sizes do not match the traction matrix");
  f.noalias() += tractionMatrix * facetTractions;
}

#define MFWAVE_INSTANTIATE(D)                                                                                    \
  template SparseMatrix assembleTractionMatrix<D>(const ParticleSet<D>&, const NeighbourList&, const Kernel&,      \
                                                  const BoundaryFacets<D>&);                                      \
  template Vector facetTractionsFromNodal<D>(const BoundaryFacets<D>&, const Vector&);                            \
  template Vector facetTractionsFromStress<D>(const BoundaryFacets<D>&, const Mat<D>&);
MFWAVE_INSTANTIATE(1)
MFWAVE_INSTANTIATE(2)
MFWAVE_INSTANTIATE(3)
#undef MFWAVE_INSTANTIATE

}  // namespace mfwave
