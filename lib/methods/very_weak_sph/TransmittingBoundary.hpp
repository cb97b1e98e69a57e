#pragma once
// The transmitting boundary of Ding-Long-Wu eqs. (31)-(32): Lysmer-Kuhlemeyer dashpots on chosen box
// faces, as a damping matrix C of the LinearSecondOrderSystem M u'' + C u' + K_sys u = f.
//
// Eq. (31): in the local frame (normal, tangents) of a facet the traction is T = -rho diag(c_p, c_s,
// c_s) V, i.e. in the global frame t = -rho Z v with Z = c_p n n^T + c_s (I - n n^T). Put into the
// traction term of eq. (19) this is f_a = -sum_{facets f of b} W_ab A_f rho Z_f v_b.
//
// No alpha: the system is (rho / alpha_a) u''_a = (K u + T t)_a (VeryWeakSph.cpp), i.e. row a of
// eq. (23) multiplied by alpha_a (eqs. (28)-(29)) was moved into the mass, and the traction matrix T
// enters the force unscaled. The dashpot is a traction term of the same row, so its C carries no
// alpha either.
//
// The velocity is the one the integrator uses for C (implicit in eq. (32): central difference with
// (M/dt + C/2) v_{n+1/2} = ..., or Newmark with the effective matrix M + gamma dt C).

#include "core/Material.hpp"
#include "core/Types.hpp"
#include "kernels/Kernel.hpp"
#include "methods/very_weak_sph/BoundaryFacets.hpp"
#include "methods/very_weak_sph/VeryWeakSphOptions.hpp"
#include "neighbours/NeighbourList.hpp"
#include "particles/ParticleSet.hpp"
#include "systems/LinearSecondOrderSystem.hpp"

#include <cstdint>

namespace mfwave {

// Z = c_p n n^T + c_s (I - n n^T) (Ding-Long-Wu eq. (31) in the global frame), n a unit normal.
template <int D>
Mat<D> dashpotImpedance(const Material& material, const Vec<D>& n) {
  const Mat<D> normalPart = n * n.transpose();
  return material.pWaveSpeed() * normalPart + material.sWaveSpeed() * (Mat<D>::Identity() - normalPart);
}

// The D N x D N damping matrix (dof = particle * D + component, physical particles only) of the
// dashpots on the box faces in `transmittingFaces` (a BoxFace mask, e.g. faceBit(BoxFace::MinusZ)).
// Assembled directly in compressed form; the result does not depend on the number of threads.
// Throws InputError("transmitting_faces") for bits of faces a D-dimensional box does not have,
// InputError("facets") when the facets do not belong to the particle set, and the errors of
// checkVeryWeakInputs ("dimension", "neighbours").
template <int D>
SparseMatrix assembleTransmittingDamping(const ParticleSet<D>& particles, const NeighbourList& neighbours,
                                         const Kernel& kernel, const BoundaryFacets<D>& facets,
                                         const Material& material, std::uint8_t transmittingFaces,
                                         DashpotLumping lumping = DashpotLumping::Particle);

// The dashpots through a given traction matrix T (D N x D F, column facet * D + component), for the
// consistent variant whose corrected T has full D x D facet blocks: C = T Z P, where P (D F x D N)
// copies each particle's velocity to its facets and Z = blockdiag(rho Z_f) over the facets on
// transmitting faces (zero blocks elsewhere). The dashpot traction t_f = -rho Z_f v (eq. (31)) then
// enters the right-hand side through exactly the weights the loads use: -C v = T t. With the
// published T this is assembleTransmittingDamping(..., DashpotLumping::Consistent).
// Throws InputError("transmitting_faces") for bits of faces a D-dimensional box does not have,
// InputError("facets") when T's columns do not match the facets.
template <int D>
SparseMatrix dashpotsThroughTractionMatrix(const SparseMatrix& tractionMatrix, const BoundaryFacets<D>& facets,
                                           const Material& material, std::uint8_t transmittingFaces);

// The Galerkin variant's dashpots (GalerkinLattice.hpp), lumped on each particle's own dofs:
// C_aa = sum over the facets f of a on transmitting faces of rho A_f Z_f, A_f = int_face W_a the
// facet's area. Block diagonal, symmetric positive semi-definite: they can only remove energy.
// Throws InputError("transmitting_faces") for bits of faces a D-dimensional box does not have.
template <int D>
SparseMatrix lumpedFacetDashpots(const BoundaryFacets<D>& facets, const Material& material,
                                 std::uint8_t transmittingFaces);

}  // namespace mfwave
