#include "methods/finite_difference/FiniteDifferenceWaveOperator.hpp"

#include "core/Error.hpp"

#include <cmath>
#include <vector>

namespace mfwave {

template <int D>
LinearSecondOrderSystem assembleFiniteDifferenceWave(const ParticleSet<D>& particles,
                                                     const NeighbourList& neighbours,
                                                     const FiniteDifferenceWaveOptions& options) {
  const Real dx = options.spacing;
  if (!(dx > 0)) throw InputError("spacing", "must be positive");
  if (!(options.density > 0)) throw InputError("density", "must be positive");
  if (!(options.modulus > 0)) throw InputError("modulus", "must be positive");
  if (particles.ghostCount() != 0)
    throw InputError("ghost_layers", "the finite-difference reference takes no ghost particles");
  const Index n = particles.size();
  if (static_cast<Index>(neighbours.offsets.size()) != n + 1)
    throw InputError("neighbours", "the neighbour list does not belong to this particle set");

  auto fixed = [&](Index i) { return (particles.faceMask[static_cast<std::size_t>(i)] & options.fixedFaces) != 0; };

  // Row i: (E V / dx^2) (2 D u_i - sum over axis neighbours u_j), with V = dx^D; the lumped mass
  // is rho V. Fixed particles keep their mass and have no stiffness row or column.
  const Real volume = std::pow(dx, D);
  const Real coupling = options.modulus * volume / (dx * dx);
  const Real tolerance = 1e-6 * dx;
  std::vector<Triplet> stiffness;
  stiffness.reserve(static_cast<std::size_t>(n) * (2 * D + 1));
  for (Index i = 0; i < n; ++i) {
    if (fixed(i)) continue;
    const Vec<D> xi = particles.position(i);
    int axisNeighbours = 0;
    for (Index s = neighbours.offsets[static_cast<std::size_t>(i)]; s < neighbours.offsets[static_cast<std::size_t>(i) + 1]; ++s) {
      const Index j = neighbours.indices[static_cast<std::size_t>(s)];
      if (j == i || std::abs((particles.position(j) - xi).norm() - dx) > tolerance) continue;
      ++axisNeighbours;
      if (!fixed(j)) stiffness.emplace_back(static_cast<int>(i), static_cast<int>(j), -coupling);
    }
    if (axisNeighbours != 2 * D)
      throw InputError("boundary", "particle " + std::to_string(i) + " has " + std::to_string(axisNeighbours) +
                                       " lattice neighbours instead of " + std::to_string(2 * D) +
                                       ": hold its face fixed");
    stiffness.emplace_back(static_cast<int>(i), static_cast<int>(i), 2 * D * coupling);
  }
  SparseMatrix k(static_cast<int>(n), static_cast<int>(n));
  k.setFromTriplets(stiffness.begin(), stiffness.end());
  SparseMatrix m(static_cast<int>(n), static_cast<int>(n));
  m.reserve(Eigen::VectorXi::Constant(static_cast<int>(n), 1));
  for (Index i = 0; i < n; ++i) m.insert(static_cast<int>(i), static_cast<int>(i)) = options.density * volume;
  return LinearSecondOrderSystem(std::move(m), SparseMatrix(), std::move(k));
}

Real finiteDifferenceFrequency(Real wavenumber, Real spacing, Real waveSpeed) {
  return 2 * waveSpeed / spacing * std::abs(std::sin(wavenumber * spacing / 2));
}

template LinearSecondOrderSystem assembleFiniteDifferenceWave<1>(const ParticleSet<1>&, const NeighbourList&,
                                                                 const FiniteDifferenceWaveOptions&);
template LinearSecondOrderSystem assembleFiniteDifferenceWave<2>(const ParticleSet<2>&, const NeighbourList&,
                                                                 const FiniteDifferenceWaveOptions&);
template LinearSecondOrderSystem assembleFiniteDifferenceWave<3>(const ParticleSet<3>&, const NeighbourList&,
                                                                 const FiniteDifferenceWaveOptions&);

}  // namespace mfwave
