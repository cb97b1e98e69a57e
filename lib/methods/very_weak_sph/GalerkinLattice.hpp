#pragma once
// The Galerkin variant of the very weak form SPH: stable by construction (issue 15).
//
// The weak form int rho u'' W_a = -int sigma(u) : grad W_a + int_boundary t W_a, with the kernel as
// both test and trial function, u = sum_b u_b W_b. The kernel is the tensor product of 1-D linear
// B-splines (tents) of half-width dx, centred on the lattice particles: a partition of unity that
// reproduces linear fields without any correction, and the RK shape function of linear basis on a
// lattice. The integrals are exact (the integrands are polynomials), so
//   K_ab = int grad W_a : C : grad W_b   (symmetric, positive semi-definite: 1/2 u^T K u is the
//                                         strain energy of the interpolated field),
//   M_a  = rho int W_a                   (row-sum lumped mass, positive),
//   f_a  = int_boundary W_a t            (the consistent load of facet tractions),
// and dashpots rho Z_f int_face W_a on the particle's own dofs are symmetric positive semi-definite.
// So every frequency is real and dashpots can only remove energy. K acts on the tent interpolant of
// u, which is exact for linear fields: the rows pass the translation and uniform-strain patch tests
// at every particle. For quadratic fields they are exact in 1-D and at interior and face particles,
// but at 2-D corners and 3-D edges and corners the mixed terms see the interpolant's bubble error
// and miss by 0.177 of the cancelling terms (GalerkinLatticeTest, docs/theory/very-weak-sph.md).
//
// On a lattice the integrals factor axis by axis (the kernel is a tensor product), so every entry
// is a product of 1-D entries: int W_p' W_q', int W_p W_q', int W_p W_q over one axis. Derivation
// and measurements: docs/theory/very-weak-sph.md, "The Galerkin variant".

#include "core/Material.hpp"
#include "core/Types.hpp"
#include "methods/very_weak_sph/BoundaryFacets.hpp"
#include "particles/ParticleSet.hpp"

#include <array>
#include <vector>

namespace mfwave {

// Where the physical particles sit on their lattice: the box corner, the spacing, the number of
// intervals per axis and each particle's lattice node.
template <int D>
struct LatticeNodes {
  Vec<D> lower;
  Real spacing = 0;
  std::array<Index, D> intervals{};
  std::vector<std::array<Index, D>> node;  // per physical particle
  std::vector<Index> particleAt;           // per lattice node (x fastest): the particle there
};

// Recovers the lattice from the physical particles (spacing from the nominal volume dx^D).
// Throws InputError("method.variant") when they do not fill a box lattice: a particle off the
// lattice, two on one node, or a node without a particle.
template <int D>
LatticeNodes<D> latticeNodes(const ParticleSet<D>& particles);

// The Galerkin system on the physical particles of a full box lattice (ghosts are not used):
// lumped mass (diagonal), stiffness K (symmetric positive semi-definite), the facets of boundary
// particles with area int_face W_a (their lumped face weights) and the traction matrix T with
// f = T t, T_{a f} = int_face W_a W_b I for facet f of particle b on the same face (exact for
// tractions linear along the face).
template <int D>
struct GalerkinLattice {
  SparseMatrix mass;
  SparseMatrix stiffness;
  BoundaryFacets<D> facets;
  SparseMatrix tractionMatrix;
};

template <int D>
GalerkinLattice<D> assembleGalerkinLattice(const ParticleSet<D>& particles, const Material& material);

}  // namespace mfwave
