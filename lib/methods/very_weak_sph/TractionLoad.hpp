#pragma once
// The boundary traction load of Ding-Long-Wu eq. (19): f_a = sum_{b in M_a^Y} W_ab A_b T(x^b, t),
// with one traction per facet (an edge or corner particle has one facet per face, each with its
// own normal and area, so a stress state gives each facet its own T = sigma n).

#include "core/Types.hpp"
#include "kernels/Kernel.hpp"
#include "methods/very_weak_sph/BoundaryFacets.hpp"
#include "neighbours/NeighbourList.hpp"
#include "particles/ParticleSet.hpp"

namespace mfwave {

// The sparse matrix T (D N x D F, F = facets.count()) with f = T t, t the facet tractions
// (dof = facet * D + component): block (a, f) = W(x^a - x^b) A_f I for facet f of particle b.
template <int D>
SparseMatrix assembleTractionMatrix(const ParticleSet<D>& particles, const NeighbourList& neighbours,
                                    const Kernel& kernel, const BoundaryFacets<D>& facets);

// Facet tractions from nodal ones (D per physical particle): each facet of a particle gets the
// particle's traction. Throws InputError("traction") for a wrong length.
template <int D>
Vector facetTractionsFromNodal(const BoundaryFacets<D>& facets, const Vector& nodalTraction);

// Facet tractions T = sigma n of a uniform stress state (the traction of a patch test).
template <int D>
Vector facetTractionsFromStress(const BoundaryFacets<D>& facets, const Mat<D>& stress);

// f += T t, eq. (19). Throws InputError("traction") for a wrong length.
void addTractionLoad(const SparseMatrix& tractionMatrix, const Vector& facetTractions, Vector& f);

}  // namespace mfwave
