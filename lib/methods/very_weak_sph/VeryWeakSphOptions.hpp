#pragma once
// Options of the very weak form SPH (Ding-Long-Wu). Every boundary correction of the paper can be
// switched off on its own, so that its effect on volumes, areas, operator and runs can be measured.

#include "core/Material.hpp"

namespace mfwave {

// Published: the scheme as printed (state u^h, lumped mass rho / alpha). Consistent: every row of
// the operator and of the traction matrix corrected to reproduce div sigma of quadratic fields
// (ConsistentCorrection.hpp); the state is the nodal displacement with mass rho (no alpha).
// Galerkin: the weak form with the lattice's tensor-product tent kernel as test and trial function
// (GalerkinLattice.hpp): symmetric positive semi-definite stiffness, lumped mass int rho W_a, stable
// without any filter; needs a full box lattice and ignores the kernel and the boundary options.
enum class VeryWeakSphVariant { Published, Consistent, Galerkin };

// The name scenes and outputs use: "published", "consistent", "galerkin".
inline const char* veryWeakSphVariantName(VeryWeakSphVariant variant) {
  switch (variant) {
    case VeryWeakSphVariant::Consistent:
      return "consistent";
    case VeryWeakSphVariant::Galerkin:
      return "galerkin";
    default:
      return "published";
  }
}

// How the published variant's transmitting dashpots (eqs. (31)-(32)) are lumped
// (TransmittingBoundary.hpp).
enum class DashpotLumping {
  // The paper's eq. (32): a transmitting particle a (one with a facet on a transmitting face k) gets
  // rho Z_k (sum over its neighbours b with a facet g on face k of W_ab A_g) times its own velocity,
  // once per such facet. Block-diagonal, symmetric positive semi-definite; interior particles whose
  // support reaches the face get nothing (their share of eq. (19) is dropped).
  Particle,
  // The traction term of eq. (19) with the dashpot traction of each neighbour facet:
  // C_ab = sum over facets g of b on transmitting faces of W_ab A_g rho Z_g. It couples neighbours
  // and has rows for interior particles within the kernel support of the face; not symmetric.
  // Particle is its row-sum lumping on the transmitting particles.
  Consistent,
};


struct VeryWeakSphOptions {
  VeryWeakSphVariant variant = VeryWeakSphVariant::Published;
  // Lame constants and density of eq. (5), (15), (23).
  Material material = Material::fromLame(1, 1, 1);
  // FV_a of eqs. (24)-(25): V_a = FV_a / sum_b W_ab with FV = 1, 1/2, 1/4, 1/8 for interior, face,
  // edge, corner particles (from the face mask). Off: FV = 1, the plain Shepard volume of eq. (4).
  bool boundaryVolumeCorrection = true;
  // FA_a of eqs. (26)-(27): A = FA / (S sum_{M^Y} W) with FA = 1 on a face, 1/2 per facet at an
  // edge, 1/4 per facet at a corner (in d dimensions 2^{1-m} for m faces). Off: FA = 1, eq. (20).
  bool boundaryAreaCorrection = true;
  // alpha_a of eqs. (28)-(29), alpha_a = 1 / sum_b W_ab V_b, applied to the whole row a, i.e. as a
  // lumped mass rho / alpha_a. Off: alpha = 1. Ignored by the Consistent variant (alpha = 1 there:
  // the corrected rows already integrate exactly, so alpha would count the cut support twice).
  bool boundaryKernelCorrection = true;
  // The boundary integral of eq. (22) (Gamma terms). Off: only the interior sum of eq. (21). The
  // Consistent variant starts its correction from whichever is chosen.
  bool boundaryIntegral = true;
  // Consistent variant: rows identical up to translation share one least-squares solve
  // (ConsistentCorrection.hpp); the result is the same to round-off. Off: every row solved on its own.
  bool reuseConsistentRowTypes = true;
};

}  // namespace mfwave
