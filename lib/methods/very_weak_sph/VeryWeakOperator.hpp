#pragma once
// The very weak form operator of Ding-Long-Wu eqs. (15), (21)-(22): one sparse matrix K (D N x D N,
// dof = particle * D + component) such that the right-hand side of eq. (23) is
//   rho u''_a = sum_b K_ab u_b + f_a,
//   K_ab = K(x^a - x^b) V_b + sum over the facets of b of Gamma(x^a - x^b; n_b) A_b.
// r = x^a - x^b, W_,j = dW/dr_j; the self term K_aa is included. Ghosts complete V and A only and
// carry no unknowns: they get no rows or columns.

#include "core/Types.hpp"
#include "kernels/Kernel.hpp"
#include "methods/very_weak_sph/BoundaryFacets.hpp"
#include "neighbours/NeighbourList.hpp"
#include "particles/ParticleSet.hpp"

#include <vector>

namespace mfwave {

// K_ik(r) = mu delta_ik W_,jj + (lambda + mu) W_,ik (Ding-Long-Wu eq. (15)): symmetric, even in r.
template <int D>
Mat<D> veryWeakInteriorBlock(const Kernel& kernel, Real lambda, Real mu, const Vec<D>& r) {
  const Mat<D> hessian = kernel.hessian(r);
  return mu * hessian.trace() * Mat<D>::Identity() + (lambda + mu) * hessian;
}

// Gamma_ik(r; n) = mu delta_ik n_j W_,j + mu n_i W_,k + lambda n_k W_,i (Ding-Long-Wu eq. (15)),
// n the outward unit normal at the boundary particle b: odd in r.
template <int D>
Mat<D> veryWeakBoundaryBlock(const Kernel& kernel, Real lambda, Real mu, const Vec<D>& r, const Vec<D>& n) {
  const Vec<D> g = kernel.gradient(r);
  return mu * n.dot(g) * Mat<D>::Identity() + mu * n * g.transpose() + lambda * g * n.transpose();
}

// Assembles K of eqs. (21)-(22) with OpenMP (rows are filled in place of a precomputed CSR layout,
// so the result does not depend on the number of threads). `volumes` are V_b of the physical
// particles; `facets` from boundaryFacets. boundaryIntegral = false leaves out the Gamma terms.
template <int D>
SparseMatrix assembleVeryWeakOperator(const ParticleSet<D>& particles, const NeighbourList& neighbours,
                                      const Kernel& kernel, Real lambda, Real mu, const std::vector<Real>& volumes,
                                      const BoundaryFacets<D>& facets, bool boundaryIntegral = true);

}  // namespace mfwave
