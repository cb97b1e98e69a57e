#pragma once
// One rank's share of a serial lattice system (issue 22), what a driver wires in place of the
// serial system under mpirun: the blocks (x kept whole unless the other axes cannot take the
// ranks, as in 1-D: whole lines run faster and sum without a chain along x; each row
// type costing its stencil entries, so the face rows' extra work is balanced too), this rank's
// DistributedLatticeSystem, and the map between the lattice's node numbers (x fastest, the
// particles' numbers on a lattice) and the rank's state.

#include "decomposition/BlockDecomposition.hpp"
#include "decomposition/mpi/DistributedLatticeSystem.hpp"

#include <mpi.h>

#include <memory>
#include <vector>

namespace mfwave {

// The cost of a row of each type that the blocks balance: its stencil's entries plus its dashpots'
// (docs/scaling.md compares it with measured step times near absorbing faces).
template <int D, int C = D>
std::vector<Real> latticeRowCosts(const LatticeSecondOrderSystem<D, C>& serial);

// C unknowns per node, as the serial system's.
template <int D, int C = D>
class LatticeShare {
 public:
  // `serial` must outlive the share. Throws as DistributedLatticeSystem and BlockDecomposition do
  // (InputError "ranks" when the lattice has too few nodes across for the rank count).
  LatticeShare(const LatticeSecondOrderSystem<D, C>& serial, MPI_Comm communicator);

  DistributedLatticeSystem<D, C>& system() { return *system_; }
  const DistributedLatticeSystem<D, C>& system() const { return *system_; }
  const BlockDecomposition<D>& decomposition() const { return *decomposition_; }
  int rank() const { return rank_; }
  int ranks() const { return ranks_; }
  // The lattice number of each node of this rank's state, in its order.
  std::vector<Index> ownedNodes() const;
  // A lattice node's place in this rank's state, or -1 when another rank owns it.
  Index localNode(Index latticeNode) const { return system_->localNode(latticeNode); }

 private:
  const LatticeSecondOrderSystem<D, C>& serial_;
  int rank_ = 0, ranks_ = 1;
  std::unique_ptr<BlockDecomposition<D>> decomposition_;
  std::unique_ptr<DistributedLatticeSystem<D, C>> system_;
};

extern template class LatticeShare<1>;
extern template class LatticeShare<2>;
extern template class LatticeShare<3>;
extern template class LatticeShare<2, 1>;
extern template class LatticeShare<3, 1>;

}  // namespace mfwave
