#include "methods/very_weak_sph/VeryWeakSph.hpp"

#include "methods/very_weak_sph/ConsistentCorrection.hpp"
#include "methods/very_weak_sph/GalerkinLattice.hpp"
#include "methods/very_weak_sph/KernelCorrection.hpp"
#include "methods/very_weak_sph/StatisticalVolume.hpp"
#include "methods/very_weak_sph/TractionLoad.hpp"
#include "methods/very_weak_sph/VeryWeakOperator.hpp"

#include <utility>

namespace mfwave {
namespace {

// The Galerkin variant (GalerkinLattice.hpp): the kernel is the lattice's tensor-product tent, so
// the kernel and neighbour list of the other variants are not used.
template <int D>
VeryWeakSph<D> assembleGalerkinVariant(const ParticleSet<D>& particles, const Material& material) {
  GalerkinLattice<D> galerkin = assembleGalerkinLattice(particles, material);
  VeryWeakSphData<D> data;
  const Index n = particles.physicalCount();
  data.volumeFraction.assign(static_cast<std::size_t>(n), 1.0);
  data.alpha.assign(static_cast<std::size_t>(n), 1.0);
  data.volume.resize(static_cast<std::size_t>(n));
  for (Index a = 0; a < n; ++a)
    data.volume[static_cast<std::size_t>(a)] = galerkin.mass.coeff(static_cast<int>(D * a), static_cast<int>(D * a)) /
                                               material.density();
  data.facets = std::move(galerkin.facets);
  data.tractionMatrix.swap(galerkin.tractionMatrix);
  VeryWeakSph<D> result{std::move(data), LinearSecondOrderSystem(std::move(galerkin.mass.markAsRValue()), SparseMatrix(),
                                                                 std::move(galerkin.stiffness.markAsRValue()))};
  result.data.operatorMatrix = result.system.stiffness();
  result.data.operatorMatrix.coeffs() *= -1;
  return result;
}

}  // namespace

template <int D>
VeryWeakSph<D> assembleVeryWeakSph(const ParticleSet<D>& particles, const NeighbourList& neighbours,
                                   const Kernel& kernel, const VeryWeakSphOptions& options) {
  if (options.variant == VeryWeakSphVariant::Galerkin) return assembleGalerkinVariant(particles, options.material);
  checkVeryWeakInputs(particles, neighbours, kernel);
  const Index n = particles.physicalCount();
  VeryWeakSphData<D> data;
  data.surfaceScale = surfaceScale(kernel);
  data.volumeFraction = volumeFractions(particles, options.boundaryVolumeCorrection);
  data.shepardSum = shepardSums(particles, neighbours, kernel);
  data.volume.resize(data.shepardSum.size());
  for (std::size_t a = 0; a < data.volume.size(); ++a)
    data.volume[a] = data.volumeFraction[a] / data.shepardSum[a];  // eq. (25)
  data.alpha = kernelCorrectionFactors(particles, neighbours, kernel, data.volume, options.boundaryKernelCorrection);
  data.facets = boundaryFacets(particles, neighbours, kernel, options.boundaryAreaCorrection);
  const Material& material = options.material;
  // Eigen 3.4 sparse matrices have no move constructor or assignment: assigning or std::move-ing
  // one copies it, so matrices here change hands by swap and K is held at most twice at any time.
  assembleVeryWeakOperator(particles, neighbours, kernel, material.lambda(), material.mu(), data.volume,
                           data.facets, options.boundaryIntegral)
      .swap(data.operatorMatrix);
  assembleTractionMatrix(particles, neighbours, kernel, data.facets).swap(data.tractionMatrix);
  if (options.variant == VeryWeakSphVariant::Consistent) {
    // Rows exact for quadratic fields: the state is the nodal displacement with mass rho, so alpha
    // (a correction of the same cut-support defect) would count it twice.
    const ConsistencyReport report = correctToQuadraticConsistency(
        particles, neighbours, kernel, data.volume, data.facets, material, data.operatorMatrix, data.tractionMatrix,
        options.reuseConsistentRowTypes);
    data.consistencyResidual = report.residual;
    data.consistentRowsSolved = report.rowsSolved;
    data.consistentDecompositions = report.decompositions;
    data.alpha.assign(data.alpha.size(), 1.0);
  }

  // Eq. (23) with eqs. (28)-(29): (rho / alpha_a) u''_a = (K u + f)_a.
  const int dofs = static_cast<int>(D * n);
  SparseMatrix mass(dofs, dofs);
  mass.reserve(Eigen::VectorXi::Constant(dofs, 1));
  for (Index a = 0; a < n; ++a)
    for (int i = 0; i < D; ++i)
      mass.insert(static_cast<int>(D * a + i), static_cast<int>(D * a + i)) =
          material.density() / data.alpha[static_cast<std::size_t>(a)];
  mass.makeCompressed();
  // -K is made in place from K and handed to the system (markAsRValue: the by-value parameter takes
  // the storage by swap; the system's member still copies it once); K is then copied back from the
  // system's -K and negated in place (assigning the expression -K would insert entry by entry into
  // a doubling buffer, up to three times K). The result is built in place, the data's matrices
  // swapped in, not copied.
  SparseMatrix stiffness, traction;
  stiffness.swap(data.operatorMatrix);
  stiffness.coeffs() *= -1;
  traction.swap(data.tractionMatrix);
  VeryWeakSph<D> result{std::move(data), LinearSecondOrderSystem(std::move(mass.markAsRValue()), SparseMatrix(),
                                                                 std::move(stiffness.markAsRValue()))};
  result.data.tractionMatrix.swap(traction);
  result.data.operatorMatrix = result.system.stiffness();
  result.data.operatorMatrix.coeffs() *= -1;
  return result;
}

template VeryWeakSph<1> assembleVeryWeakSph<1>(const ParticleSet<1>&, const NeighbourList&, const Kernel&,
                                               const VeryWeakSphOptions&);
template VeryWeakSph<2> assembleVeryWeakSph<2>(const ParticleSet<2>&, const NeighbourList&, const Kernel&,
                                               const VeryWeakSphOptions&);
template VeryWeakSph<3> assembleVeryWeakSph<3>(const ParticleSet<3>&, const NeighbourList&, const Kernel&,
                                               const VeryWeakSphOptions&);

}  // namespace mfwave
