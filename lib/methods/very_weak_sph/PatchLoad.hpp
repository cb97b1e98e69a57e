#pragma once
// The surface patch load of the Lamb test, Ding-Long-Wu eqs. (36)-(37): a traction t f(t) on a
// rectangle of one box face, X(x) = 1 inside the rectangle.
//
// Why fractional weights: sampling X at the lattice nodes (eq. (37) read literally) loads whole
// nodes or none, so the discrete resultant jumps with the lattice (1/4 or 2.25 times the exact
// one for a half-width equal to the spacing, depending on < or <=). Here every physical particle
// of the face carries the fraction of its tributary cell covered by the rectangle: the cell is a
// spacing^(D-1) square centred at the particle and clipped to the face (a particle on an edge of
// the face has half a cell, a corner a quarter). The cells tile the face, so
//   sum_a weight_a spacing^(D-1) = |rectangle intersect face|
// exactly, for any rectangle, aligned with the lattice or not.

#include "core/Types.hpp"
#include "methods/very_weak_sph/BoundaryFacets.hpp"
#include "particles/ParticleSet.hpp"

#include <vector>

namespace mfwave {

// The covered cell fraction of every physical particle (0 for particles not on `face`, BoxFace
// numbering). `centre` and `halfWidths` give the rectangle [centre - halfWidths, centre + halfWidths]
// in the face's plane; their entries along the face's normal axis are ignored. The box
// [boxLower, boxUpper] is the lattice's (the face extent the cells are clipped to).
// Throws InputError("patch.face") for a face the D-dimensional box does not have,
// InputError("patch.half_widths") for negative or non-finite half-widths, InputError("spacing")
// for spacing <= 0, InputError("geometry") for boxUpper <= boxLower on some axis.
template <int D>
std::vector<Real> patchLoadWeights(const ParticleSet<D>& particles, int face, const Vec<D>& centre,
                                   const Vec<D>& halfWidths, Real spacing, const Vec<D>& boxLower,
                                   const Vec<D>& boxUpper);

// Facet tractions (dof = facet * D + component, as facetTractionsFromNodal) carrying
// weight_a * traction on the facets of `face` only: an edge or corner particle of the loaded face
// has facets on other faces too, and the load is not theirs. Zero elsewhere. The load of eq. (19)
// is then f = T t with T = assembleTractionMatrix(...), scaled by the time function f(t).
// Throws InputError("patch.weights") when weights does not have one entry per physical particle,
// InputError("patch.face") for a negative face.
template <int D>
Vector patchFacetTractions(const BoundaryFacets<D>& facets, int face, const std::vector<Real>& weights,
                           const Vec<D>& traction);

// The Galerkin variant's load (GalerkinLattice.hpp) is the exact int_patch W_a t of the tent kernel
// W_a (the tensor product of 1-D tents of half-width `spacing`, cut at the box): the weight of
// particle a is int_{rectangle intersect face} W_a / spacing^(D-1), so that, like the cell
// fractions, sum_a weight_a spacing^(D-1) = |rectangle intersect face|. Same arguments and errors
// as patchLoadWeights.
template <int D>
std::vector<Real> patchTentWeights(const ParticleSet<D>& particles, int face, const Vec<D>& centre,
                                   const Vec<D>& halfWidths, Real spacing, const Vec<D>& boxLower,
                                   const Vec<D>& boxUpper);

// The nodal force weight_a spacing^(D-1) traction on every physical particle (dof a * D + i), for
// weights from patchTentWeights: the Galerkin load without a traction matrix.
template <int D>
Vector patchNodalForce(const std::vector<Real>& weights, Real spacing, const Vec<D>& traction);

}  // namespace mfwave
