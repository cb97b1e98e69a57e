#pragma once
// M u'' + K u = 0 on a box lattice, one rank's share (issue 22): the same stencils as the serial
// LatticeSecondOrderSystem, the state of the nodes this rank owns only, the halo of u exchanged
// once per acceleration. Any SecondOrderSystem integrator steps it unchanged on the owned vectors
// (integrators never see particles, nor ranks), and since every owned node's acceleration is the
// serial one bit for bit (LocalStencils, the same inverse mass blocks, the same expressions as
// LatticeSecondOrderSystem::fusedSolve), a run on any number of ranks keeps the serial bits.
// The energies are summed in the serial order over the ranks (LineSums.hpp).
//
// This first step covers undamped systems without loads; dashpots, loads and prescribed
// displacements come next (docs/scaling.md).

#include "decomposition/LocalStencils.hpp"
#include "decomposition/mpi/HaloExchange.hpp"
#include "lattice/LatticeSecondOrderSystem.hpp"
#include "systems/SecondOrderSystem.hpp"

#include <mpi.h>

#include <memory>
#include <vector>

namespace mfwave {

template <int D>
class DistributedLatticeSystem : public SecondOrderSystem {
 public:
  // `decomposition` must keep x whole (the energies' order) and outlive this object. Throws
  // InputError("damping") for a system with dashpots, InputError("loads") for one with loads,
  // InputError("ranks") for a decomposition that splits x.
  DistributedLatticeSystem(const LatticeSecondOrderSystem<D>& serial, const BlockDecomposition<D>& decomposition,
                           int rank, MPI_Comm communicator);

  // D values per owned node, in the owned box's order.
  Index size() const override { return D * owned().count(); }
  bool dependsOnVelocity() const override { return false; }
  void acceleration(Real t, Eigen::Ref<const Vector> u, Eigen::Ref<const Vector> v, Eigen::Ref<Vector> a) override;

  // Over all ranks, bitwise the serial system's (every rank gets the total).
  Real kineticEnergy(const Vector& v) const;
  Real strainEnergy(const Vector& u);

  const Box<D>& owned() const { return exchange_->plan().owned(); }
  // The halo exchange of each acceleration (its plan, bytes and messages).
  const HaloExchange<D>& exchange() const { return *exchange_; }
  // The owned part of a whole-lattice vector (D values per node).
  Vector restrict(const Vector& whole) const;

 private:
  // u into the local box, halo exchanged; then K u for the owned rows into ku_.
  void applyStiffness(const Real* u);

  const LatticeSecondOrderSystem<D>& serial_;
  const BlockDecomposition<D>& decomposition_;
  int rank_;
  MPI_Comm communicator_;
  std::unique_ptr<HaloExchange<D>> exchange_;
  std::unique_ptr<LocalStencils<D>> stiffness_;
  std::vector<Real> inverseMass_;  // per type (LatticeSecondOrderSystem::inverseBlocks(0))
  std::vector<Index> massFlat_;    // zeros: the mass is block-diagonal
  std::vector<Real> local_, ku_;
};

extern template class DistributedLatticeSystem<1>;
extern template class DistributedLatticeSystem<2>;
extern template class DistributedLatticeSystem<3>;

}  // namespace mfwave
