#pragma once
// M u'' + C u' + K u = f(t) on a box lattice, one rank's share (issue 22): the same stencils as the
// serial LatticeSecondOrderSystem, the state of the nodes this rank owns only, the halo of u
// exchanged once per stiffness product. Any integrator of a LinearOperatorSystem steps it unchanged
// on the owned vectors (integrators never see particles, nor ranks): central difference takes its
// dashpot solve (Ding-Long-Wu eq. (32)) from centredDamping(), the energy ledger its energies and
// load work from the methods below. Every owned node's acceleration is the serial one bit for bit
// (LocalStencils, the same inverse blocks, the same expressions as
// LatticeSecondOrderSystem::fusedSolve, the loads added in the same order), so a run on any number
// of ranks keeps the serial bits; the energies, the dashpot power and dot() are summed in the
// serial order over the ranks (LineSums.hpp), so every rank's figures are the serial ones too.
//
// Covered: dashpots on each node's own dofs (block-diagonal C, the Galerkin very weak SPH's
// transmitting faces) and dashpots that couple nodes (the consistent variant's: C v through its own
// halo, the surface block of eq. (32) solved whole on every rank), loads given as nonzero entries
// (SparseLoads.hpp), prescribed displacements (eq. (30)) where M + dt/2 C is block diagonal. Not
// yet: prescribed displacements beside dashpots that couple nodes (docs/scaling.md).

#include "decomposition/mpi/RankStencilProduct.hpp"
#include "lattice/LatticeSecondOrderSystem.hpp"
#include "systems/LinearOperatorSystem.hpp"

#include <mpi.h>

#include <memory>
#include <optional>
#include <vector>

namespace mfwave {

// C unknowns per node, as the serial system's (LatticeSecondOrderSystem<D, C>).
template <int D, int C = D>
class DistributedLatticeSystem : public LinearOperatorSystem {
 public:
  // `serial` and `decomposition` must outlive this object; any decomposition (x split too: the
  // sums then chain along x, LineSums.hpp). Throws InputError("loads") for a force given as a
  // function rather than as sparse loads.
  DistributedLatticeSystem(const LatticeSecondOrderSystem<D, C>& serial, const BlockDecomposition<D>& decomposition,
                           int rank, MPI_Comm communicator);

  // C values per owned node, in the owned box's order.
  Index size() const override { return C * owned().count(); }
  bool hasDamping() const override { return serial_.hasDamping(); }
  // This rank's communicator and the sum of the ranks' sizes: the ARKODE integrators then run on
  // SUNDIALS' MPI vectors (integrators/ArkodeMpiVectors.hpp, which the constructor enables), so
  // their adaptive steps are chosen from norms over all the ranks.
  // Their norms sum in the serial lattice order (dot), so adaptive steps are the serial ones too.
  std::optional<VectorDistribution> distribution() const override;
  void acceleration(Real t, Eigen::Ref<const Vector> u, Eigen::Ref<const Vector> v, Eigen::Ref<Vector> a) override;

  // The owned part of f(t).
  void force(Real t, Vector& f) const override;
  // The owned rows of K x (x owned; its halo is exchanged).
  void applyStiffness(const Vector& x, Vector& y) const override;
  // Over all ranks, bitwise the serial system's (every rank gets the total; every rank must call).
  Real kineticEnergy(const Vector& v) const override;
  Real strainEnergy(const Vector& u) const override;
  Real dampingPower(const Vector& v) const override;
  Real dot(const Vector& a, const Vector& b) const override;
  // The owned part of the serial figures, from the per-type values (nothing of the whole lattice).
  Vector lumpedMass() const override;
  Vector stiffnessAbsoluteRowSums() const override;
  // The largest over the ranks; each owned value from its lattice dof's number (node * C + c).
  Real maximum(Real value) const override;
  void fillByGlobalIndex(Vector& x, const std::function<Real(Index)>& value) const override;
  // Eq. (32) with (M + dt/2 C)^-1 per row type, prescribed dofs (this rank's, in its numbering)
  // imposed node by node as the serial system does. Throws InputError("prescribed_displacement")
  // for prescribed dofs beside dashpots that couple nodes.
  std::unique_ptr<CentredDampingSolve> centredDamping(Real dt, const std::vector<Index>& prescribedDofs) const override;

  const Box<D>& owned() const { return stiffness_->owned(); }
  // The halo exchange of each stiffness product (its plan, bytes and messages).
  const HaloExchange<D>& exchange() const { return stiffness_->exchange(); }
  // The owned part of a whole-lattice vector (C values per node).
  Vector restrict(const Vector& whole) const;
  // A lattice node's place in this rank's state, or -1 when another rank owns it.
  Index localNode(Index latticeNode) const;
  // B_type (f - K u - C v) for every owned node into a: the acceleration with B = M^-1, the dashpot
  // solve of eq. (32) with B = (M + dt/2 C)^-1 (LatticeSecondOrderSystem::fusedSolve's rows).
  void solve(const std::vector<Real>& inverseBlocks, Real t, const Real* u, const Real* v, Real* a) const;

 private:
  // f(k, type) for every owned node k (in the owned box's order) and its row type; f must only
  // write what belongs to node k (lines run on threads).
  template <class Function>
  void forEachOwnedNode(Function&& f) const;
  // The sum over all ranks' owned nodes of g(k, type) (k the owned node, in its box's order), in
  // the serial order.
  template <class Function>
  Real sumOverOwnedNodes(Function&& g) const;

  const LatticeSecondOrderSystem<D, C>& serial_;
  const BlockDecomposition<D>& decomposition_;
  int rank_;
  MPI_Comm communicator_;
  Index globalSize_ = 0;  // sum over the ranks of size()
  std::unique_ptr<RankStencilProduct<D, C>> stiffness_;
  std::unique_ptr<RankStencilProduct<D, C>> damping_;  // dashpots that couple nodes only
  std::vector<char> allRowByRow_;                   // damping_'s rows, all row by row
  mutable std::vector<Real> cv_;                    // C v of the owned rows (damping_)
  std::vector<Real> inverseMass_;  // per type (LatticeSecondOrderSystem::inverseBlocks(0))
  std::vector<Index> nodeFlat_;    // zeros: the mass and dashpots act on a node's own dofs
  std::vector<SparseLoad> loads_;  // the owned entries, dofs owned
  std::vector<char> dashpotTypes_; // per row type: has dashpots
};

extern template class DistributedLatticeSystem<1>;
extern template class DistributedLatticeSystem<2>;
extern template class DistributedLatticeSystem<3>;
extern template class DistributedLatticeSystem<2, 1>;
extern template class DistributedLatticeSystem<3, 1>;

}  // namespace mfwave
