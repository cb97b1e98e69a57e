#include "methods/very_weak_sph/TransmittingBoundary.hpp"

#include "core/Error.hpp"
#include "methods/very_weak_sph/StatisticalVolume.hpp"
#include "particles/BoxFace.hpp"

#include <string>
#include <utility>
#include <vector>

namespace mfwave {
namespace {

template <int D>
using BlockRow = std::vector<std::pair<Index, Mat<D>>>;  // (column particle, D x D block)

bool onTransmittingFace(std::uint8_t mask, int face) { return (mask & faceBit(face)) != 0; }

// Throws InputError("transmitting_faces") for bits of faces a D-dimensional box does not have.
template <int D>
void checkTransmittingMask(std::uint8_t transmittingFaces) {
  if ((transmittingFaces & ~allFaces(D)) != 0)
    throw InputError("transmitting_faces", "mask " + std::to_string(transmittingFaces) + " has faces that a " +
                                               std::to_string(D) + "-D box does not have");
}

// Ding-Long-Wu eq. (32): rho Z_k (sum_b W_ab A_b) on particle a, for each of its facets on a
// transmitting face k; the sum runs over the neighbours' facets on the same face k.
template <int D>
BlockRow<D> particleRow(const ParticleSet<D>& particles, const NeighbourList& neighbours, const Kernel& kernel,
                        const BoundaryFacets<D>& facets, const Material& material, std::uint8_t mask, Index a) {
  const Index n = particles.physicalCount();
  const Vec<D> xa = particles.position(a);
  Mat<D> block = Mat<D>::Zero();
  bool any = false;
  for (Index f = facets.begin(a); f < facets.end(a); ++f) {
    const int face = facets.face[static_cast<std::size_t>(f)];
    if (!onTransmittingFace(mask, face)) continue;
    Real weight = 0;
    for (Index b : neighbours.row(a)) {
      if (b >= n) continue;  // ghosts carry no facets
      for (Index g = facets.begin(b); g < facets.end(b); ++g)
        if (facets.face[static_cast<std::size_t>(g)] == face)
          weight += kernel.value(Vec<D>(xa - particles.position(b))) * facets.area[static_cast<std::size_t>(g)];
    }
    block += material.density() * weight * dashpotImpedance<D>(material, facets.normal[static_cast<std::size_t>(f)]);
    any = true;
  }
  BlockRow<D> row;
  if (any) row.emplace_back(a, block);
  return row;
}

// Eq. (19) with the dashpot traction of eq. (31) at every neighbour facet on a transmitting face:
// block (a, b) = sum_g W_ab A_g rho Z_g.
template <int D>
BlockRow<D> consistentRow(const ParticleSet<D>& particles, const NeighbourList& neighbours, const Kernel& kernel,
                          const BoundaryFacets<D>& facets, const Material& material, std::uint8_t mask, Index a) {
  const Index n = particles.physicalCount();
  const Vec<D> xa = particles.position(a);
  BlockRow<D> row;
  for (Index b : neighbours.row(a)) {
    if (b >= n) continue;
    Mat<D> block = Mat<D>::Zero();
    bool any = false;
    for (Index g = facets.begin(b); g < facets.end(b); ++g) {
      const auto gi = static_cast<std::size_t>(g);
      if (!onTransmittingFace(mask, facets.face[gi])) continue;
      block += kernel.value(Vec<D>(xa - particles.position(b))) * facets.area[gi] * material.density() *
               dashpotImpedance<D>(material, facets.normal[gi]);
      any = true;
    }
    if (any) row.emplace_back(b, block);
  }
  return row;
}

}  // namespace

template <int D>
SparseMatrix assembleTransmittingDamping(const ParticleSet<D>& particles, const NeighbourList& neighbours,
                                         const Kernel& kernel, const BoundaryFacets<D>& facets,
                                         const Material& material, std::uint8_t transmittingFaces,
                                         DashpotLumping lumping) {
  checkVeryWeakInputs(particles, neighbours, kernel);
  checkTransmittingMask<D>(transmittingFaces);
  const Index n = particles.physicalCount();
  if (static_cast<Index>(facets.offsets.size()) != n + 1 ||
      facets.face.size() != facets.particle.size() || facets.area.size() != facets.particle.size() ||
      facets.normal.size() != facets.particle.size())
    throw InputError("facets", "the facets do not belong to this particle set");

  // Rows are computed independently (one thread each, fixed order), then gathered serially: the
  // matrix does not depend on the number of threads.
  std::vector<BlockRow<D>> rows(static_cast<std::size_t>(n));
#pragma omp parallel for schedule(dynamic, 64)
  for (Index a = 0; a < n; ++a)
    rows[static_cast<std::size_t>(a)] =
        lumping == DashpotLumping::Particle
            ? particleRow(particles, neighbours, kernel, facets, material, transmittingFaces, a)
            : consistentRow(particles, neighbours, kernel, facets, material, transmittingFaces, a);

  std::vector<Eigen::Triplet<Real, int>> triplets;
  for (Index a = 0; a < n; ++a)
    for (const auto& [b, block] : rows[static_cast<std::size_t>(a)])
      for (int i = 0; i < D; ++i)
        for (int k = 0; k < D; ++k)
          if (block(i, k) != 0)
            triplets.emplace_back(static_cast<int>(D * a + i), static_cast<int>(D * b + k), block(i, k));
  SparseMatrix damping(static_cast<int>(D * n), static_cast<int>(D * n));
  damping.setFromTriplets(triplets.begin(), triplets.end());
  return damping;
}

template <int D>
SparseMatrix dashpotsThroughTractionMatrix(const SparseMatrix& tractionMatrix, const BoundaryFacets<D>& facets,
                                           const Material& material, std::uint8_t transmittingFaces) {
  checkTransmittingMask<D>(transmittingFaces);
  const Index n = static_cast<Index>(facets.offsets.size()) - 1;
  if (n < 0 || tractionMatrix.cols() != D * facets.count() || tractionMatrix.rows() != D * n ||
      facets.face.size() != facets.particle.size() || facets.normal.size() != facets.particle.size())
    throw InputError("facets", "the facets do not match the traction matrix");
  // Z P: facet f's rows take rho Z_f times the velocity of its particle (eq. (31)).
  std::vector<Eigen::Triplet<Real, int>> triplets;
  for (Index f = 0; f < facets.count(); ++f) {
    const auto fi = static_cast<std::size_t>(f);
    if (!onTransmittingFace(transmittingFaces, facets.face[fi])) continue;
    const Mat<D> z = material.density() * dashpotImpedance<D>(material, facets.normal[fi]);
    for (int l = 0; l < D; ++l)
      for (int k = 0; k < D; ++k)
        if (z(l, k) != 0)
          triplets.emplace_back(static_cast<int>(D * f + l), static_cast<int>(D * facets.particle[fi] + k), z(l, k));
  }
  SparseMatrix impedance(static_cast<int>(D * facets.count()), static_cast<int>(D * n));
  impedance.setFromTriplets(triplets.begin(), triplets.end());
  SparseMatrix damping = tractionMatrix * impedance;
  damping.prune(0.0);
  return damping;
}

template <int D>
SparseMatrix lumpedFacetDashpots(const BoundaryFacets<D>& facets, const Material& material,
                                 std::uint8_t transmittingFaces) {
  checkTransmittingMask<D>(transmittingFaces);
  const Index n = static_cast<Index>(facets.offsets.size()) - 1;
  std::vector<Eigen::Triplet<Real, int>> triplets;
  for (Index f = 0; f < facets.count(); ++f) {
    const auto fi = static_cast<std::size_t>(f);
    if (!onTransmittingFace(transmittingFaces, facets.face[fi])) continue;
    const Mat<D> z = material.density() * facets.area[fi] * dashpotImpedance<D>(material, facets.normal[fi]);
    const Index a = facets.particle[fi];
    for (int l = 0; l < D; ++l)
      for (int k = 0; k < D; ++k)
        if (z(l, k) != 0) triplets.emplace_back(static_cast<int>(D * a + l), static_cast<int>(D * a + k), z(l, k));
  }
  SparseMatrix damping(static_cast<int>(D * n), static_cast<int>(D * n));
  damping.setFromTriplets(triplets.begin(), triplets.end());
  return damping;
}

#define MFWAVE_INSTANTIATE(D)                                                                               \
  template SparseMatrix assembleTransmittingDamping<D>(const ParticleSet<D>&, const NeighbourList&,         \
                                                       const Kernel&, const BoundaryFacets<D>&,              \
                                                       const Material&, std::uint8_t, DashpotLumping);        \
  template SparseMatrix dashpotsThroughTractionMatrix<D>(const SparseMatrix&, const BoundaryFacets<D>&,     \
                                                         const Material&, std::uint8_t);                   \
  template SparseMatrix lumpedFacetDashpots<D>(const BoundaryFacets<D>&, const Material&, std::uint8_t);
MFWAVE_INSTANTIATE(1)
MFWAVE_INSTANTIATE(2)
MFWAVE_INSTANTIATE(3)
#undef MFWAVE_INSTANTIATE

}  // namespace mfwave
