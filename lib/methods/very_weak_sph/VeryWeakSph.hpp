#pragma once
// The very weak form SPH of Ding-Long-Wu as published, as a method of the pipeline: particles
// (physical, optionally followed by ghost layers) and neighbours in, a LinearSecondOrderSystem
//   M u'' + K_sys u = f,  M = diag(rho / alpha_a),  K_sys = -K  (K of eqs. (21)-(22))
// out, with the method data for diagnostics. Eq. (23) reads rho u'' = K u + f; multiplying row a
// by alpha_a (eqs. (28)-(29)) is the lumped mass rho / alpha_a.
//
// With options.variant = Consistent the operator and traction matrices are corrected row by row to
// reproduce div sigma of every quadratic field (ConsistentCorrection.hpp); the state is then the
// nodal displacement, M = rho I, alpha = 1 and K_sys = -K_corrected. Loads and dashpots must go
// through the corrected data.tractionMatrix (dashpotsThroughTractionMatrix).
//
// With options.variant = Galerkin (GalerkinLattice.hpp) M = diag(rho int W_a), K_sys is the
// symmetric positive semi-definite Galerkin stiffness, data.facets carry the face weights int W_a
// and data.tractionMatrix the face's consistent mass; volume = int W_a, alpha = 1.
//
// The rest of the method plugs in around this system: transmitting dashpots (eqs. (31)-(32),
// TransmittingBoundary: system.setDamping), traction and patch loads (eq. (19), TractionLoad and
// PatchLoad: system.setForce), displacement conditions (eq. (30): the integrator's prescribed
// dofs), conservative smoothing (eq. (33), ConservativeSmoothing: the integrator's velocity
// filter) and deconvolution of what is reported (eq. (35), Deconvolution).

#include "core/Types.hpp"
#include "kernels/Kernel.hpp"
#include "methods/very_weak_sph/BoundaryFacets.hpp"
#include "methods/very_weak_sph/VeryWeakSphOptions.hpp"
#include "neighbours/NeighbourList.hpp"
#include "particles/ParticleSet.hpp"
#include "systems/LinearSecondOrderSystem.hpp"

#include <vector>

namespace mfwave {

template <int D>
struct VeryWeakSphData {
  Real surfaceScale = 0;              // S of eq. (20)
  std::vector<Real> volumeFraction;   // FV_a, eq. (24)
  std::vector<Real> shepardSum;       // sum_{b in M_a} W_ab (ghosts included)
  std::vector<Real> volume;           // V_a, eq. (25)
  std::vector<Real> alpha;            // alpha_a, eq. (29) (1 with the correction off)
  BoundaryFacets<D> facets;           // normals and areas A, eq. (27)
  SparseMatrix operatorMatrix;        // K: rho u'' = K u + f (eq. (23), before alpha); corrected if Consistent;
                                      // Galerkin: M u'' = K u + f with M = diag(rho int W_a)
  SparseMatrix tractionMatrix;        // T: f = T t for facet tractions t (eq. (19)); corrected if Consistent
  // Consistent variant only (ConsistentCorrection.hpp): the largest relative residual of the
  // quadratic patch conditions over all rows, the number of particle rows corrected (0 if Published)
  // and of the decompositions computed for them (one per row type when rows are reused).
  Real consistencyResidual = 0;
  Index consistentRowsSolved = 0;
  Index consistentDecompositions = 0;
};

template <int D>
struct VeryWeakSph {
  VeryWeakSphData<D> data;
  LinearSecondOrderSystem system;     // f = 0; attach loads with system.setForce
};

// Throws InputError("dimension") when the kernel is not D-dimensional, InputError("neighbours")
// when the list lacks rows for physical particles; for the Consistent variant, Error naming the
// particle whose row cannot reproduce the quadratic fields.
template <int D>
VeryWeakSph<D> assembleVeryWeakSph(const ParticleSet<D>& particles, const NeighbourList& neighbours,
                                   const Kernel& kernel, const VeryWeakSphOptions& options);

}  // namespace mfwave
