#pragma once
// M + dt/2 C of Ding-Long-Wu eq. (32) for dashpots that couple particles (the consistent very weak
// SPH's, through its corrected traction rows), assembled and factorised on the nodes the dashpots
// reach only: the dashpot rows and their columns, a few layers under the transmitting faces, so
// its size follows the surface. Prescribed dofs among those nodes get identity rows, so the solve
// imposes their accelerations. The serial lattice system's dashpot solve uses it, and so does each
// rank of a distributed one (lib/decomposition), whose replicated copies solve bit for bit alike.

#include "lattice/LatticeSecondOrderSystem.hpp"
#include "solvers/FactorisedMatrix.hpp"

#include <utility>
#include <vector>

namespace mfwave {

template <int D, int C = D>
class DashpotSurfaceSolve {
 public:
  // Throws InputError("prescribed_displacement") for a dof outside the system.
  DashpotSurfaceSolve(const LatticeSecondOrderSystem<D, C>& system, Real dt, const std::vector<Index>& prescribedDofs);

  // The lattice nodes of the block, sorted: its unknowns are C per node in this order.
  const std::vector<Index>& nodes() const { return nodes_; }
  // The prescribed dofs inside the block: (its row, the dof's position in the prescribed list).
  const std::vector<std::pair<Index, Index>>& inside() const { return inside_; }
  // The prescribed dofs elsewhere: (the dof, its position in the prescribed list).
  const std::vector<std::pair<Index, Index>>& outside() const { return outside_; }
  // The block's right-hand side at its node k: M times the acceleration `a` of that node (its C
  // values), the node's mass block summed per type as the lattice system keeps it.
  void massTimes(const LatticeSecondOrderSystem<D, C>& system, std::size_t k, const Real* a, Real* out) const {
    Real block[C * C];
    const LatticeRowTypes<D>& types = system.types();
    system.mass().typeSum(types.typeOf(types.node(nodes_[k])), block);
    for (int c = 0; c < C; ++c) {
      Real s = 0;
      for (int d = 0; d < C; ++d) s += block[C * c + d] * a[d];
      out[c] = s;
    }
  }
  // solution = (M + dt/2 C)^-1 rhs on the block.
  void solve(const Vector& rhs, Vector& solution) const { solver_.solve(rhs, solution); }

 private:
  std::vector<Index> nodes_;
  std::vector<std::pair<Index, Index>> inside_, outside_;
  FactorisedMatrix solver_;
};

extern template class DashpotSurfaceSolve<1>;
extern template class DashpotSurfaceSolve<2>;
extern template class DashpotSurfaceSolve<3>;
extern template class DashpotSurfaceSolve<2, 1>;
extern template class DashpotSurfaceSolve<3, 1>;

}  // namespace mfwave
