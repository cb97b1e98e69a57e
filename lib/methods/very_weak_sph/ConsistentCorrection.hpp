#pragma once
// The consistent variant of the very weak form SPH: each particle's row of the published operator
// (eqs. (21)-(22)) and of its traction matrix (eq. (19)) takes the smallest kernel-weighted change
// after which the row returns div sigma(u)(x^a) exactly for every displacement field whose
// components are polynomials of degree <= 2, with the facet tractions t_f = sigma(u)(x_f) n_f.
//
// Why: as published the row sums and the boundary moments are quadrature errors of O(1) (theory
// notes, "The published scheme's defects"), so the scheme does not converge. Exact reproduction of
// quadratic fields is the patch test of a second-order operator, and it is what makes the
// consistent variant converge (docs/references.md, reading 3).
//
// Per particle a the right-hand side is rho u''_a = sum_b G_ab u_b + sum_f T_af t_f (b its physical
// neighbours, f the facets of those neighbours). For the scalar row (a, i) the unknowns are the
// entries G_ab(i, k) and T_af(i, l) (full D x D traction blocks, where the published T is W A I),
// and the D (D+1)(D+2)/2 fields u = e_k m(x), m a monomial in (x - x^a)/h, give linear constraints
// A_a x = target_i. The change is delta = W A^T (A W A^T)^+ (target_i - A x_published), W the
// diagonal of kernel weights: W_ab V_b for a particle entry and W_ab A_f h for a facet entry (both
// the share of the kernel's mass the entry carries, so they are comparable; the columns are made
// dimensionless first, G in units (lambda + 2 mu) / h^2 and T in units 1 / h). The correction of
// every entry is thus its weight times a polynomial, the reproducing-kernel (corrective SPH) form.
// Computed as W^{1/2} (A W^{1/2})^+ r with a complete orthogonal decomposition, because A is rank
// deficient at boundaries (two layers normal to a face, eight neighbours at a corner): the facet
// tractions supply the moments the particles cannot.

#include "core/Material.hpp"
#include "core/Types.hpp"
#include "kernels/Kernel.hpp"
#include "methods/very_weak_sph/BoundaryFacets.hpp"
#include "neighbours/NeighbourList.hpp"
#include "particles/ParticleSet.hpp"

#include <vector>

namespace mfwave {

struct ConsistencyReport {
  // Largest relative residual over all rows and fields: |row(u) - div sigma(u)(x^a)| divided by the
  // sum of the absolute values of the row's terms and of the target (so 1e-16 is round-off).
  Real residual = 0;
  // Particle rows corrected (all physical particles).
  Index rowsSolved = 0;
  // Decompositions computed, one per particle row type (each shared by the D components): equal to
  // rowsSolved without reuse or on an irregular cloud, a few hundred on a lattice block.
  Index decompositions = 0;
};

// Replaces operatorMatrix (D N x D N, dof = particle * D + component) and tractionMatrix
// (D N x D F, column facet * D + component) by their corrected forms. On input they hold the
// published matrices (or any starting weights within the kernel supports); on output the operator
// has a full D x D block for every physical neighbour, the traction matrix one for every facet of
// a physical neighbour. Rows are solved independently with OpenMP into a precomputed layout, so the
// result does not depend on the number of threads. With reuseRowTypes, rows whose inputs agree to
// 1e-9 in units of h (RowTypes.hpp: offsets, volumes, facets and starting weights; translates on a
// lattice) share one decomposition: each takes its representative's change delta on top of its own
// starting weights, and its residual is checked on its own constraints. Translates differ by
// round-off only, so the result equals the unshared one to round-off (tested to 1e-13). Throws Error naming the particle when a row's
// residual exceeds `tolerance` (too few neighbours and facets to reproduce the fields) or when an
// input entry lies outside the row's neighbours (the inputs are released while the rows are solved,
// to hold K at most twice, so after that Error both matrices are empty); InputError("volumes") / ("facets") / ("operator")
// for inputs of the wrong size.
template <int D>
ConsistencyReport correctToQuadraticConsistency(const ParticleSet<D>& particles, const NeighbourList& neighbours,
                                                const Kernel& kernel, const std::vector<Real>& volumes,
                                                const BoundaryFacets<D>& facets, const Material& material,
                                                SparseMatrix& operatorMatrix, SparseMatrix& tractionMatrix,
                                                bool reuseRowTypes = true, Real tolerance = 1e-10);

}  // namespace mfwave
