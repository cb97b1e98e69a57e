#include "decomposition/mpi/LatticeShare.hpp"

namespace mfwave {

template <int D, int C>
std::vector<Real> latticeRowCosts(const LatticeSecondOrderSystem<D, C>& serial) {
  std::vector<Real> cost(static_cast<std::size_t>(serial.stiffness().typeCount()));
  for (Index type = 0; type < serial.stiffness().typeCount(); ++type) {
    cost[static_cast<std::size_t>(type)] = static_cast<Real>(serial.stiffness().end(type) - serial.stiffness().begin(type));
    if (serial.hasDamping())
      cost[static_cast<std::size_t>(type)] += static_cast<Real>(serial.damping().end(type) - serial.damping().begin(type));
  }
  return cost;
}

template <int D, int C>
LatticeShare<D, C>::LatticeShare(const LatticeSecondOrderSystem<D, C>& serial, MPI_Comm communicator) : serial_(serial) {
  MPI_Comm_rank(communicator, &rank_);
  MPI_Comm_size(communicator, &ranks_);
  const std::vector<Real> cost = latticeRowCosts<D, C>(serial);
  // x whole when the other axes can take the ranks: a whole line runs its middle through one
  // stencilRun and its sums need no chain along x. Else (always in 1-D, or too few nodes across)
  // x is cut too, and the sums chain the pieces of each line in x order (LineSums.hpp).
  std::array<bool, D> splittable = BlockDecomposition<D>::allAxes();
  splittable[0] = false;
  if (!BlockDecomposition<D>::fits(serial.types().nodes(), ranks_, splittable)) splittable[0] = true;
  decomposition_ = std::make_unique<BlockDecomposition<D>>(serial.types(), ranks_, cost, splittable);
  system_ = std::make_unique<DistributedLatticeSystem<D, C>>(serial, *decomposition_, rank_, communicator);
}

template <int D, int C>
std::vector<Index> LatticeShare<D, C>::ownedNodes() const {
  Box<D> all;
  all.hi = serial_.types().nodes();
  std::vector<Index> nodes;
  nodes.reserve(static_cast<std::size_t>(system_->owned().count()));
  system_->owned().forEachNode([&](const std::array<Index, D>& node) { nodes.push_back(all.localIndex(node)); });
  return nodes;
}

template std::vector<Real> latticeRowCosts<1, 1>(const LatticeSecondOrderSystem<1, 1>&);
template std::vector<Real> latticeRowCosts<2, 2>(const LatticeSecondOrderSystem<2, 2>&);
template std::vector<Real> latticeRowCosts<3, 3>(const LatticeSecondOrderSystem<3, 3>&);
template std::vector<Real> latticeRowCosts<2, 1>(const LatticeSecondOrderSystem<2, 1>&);
template std::vector<Real> latticeRowCosts<3, 1>(const LatticeSecondOrderSystem<3, 1>&);
template class LatticeShare<1>;
template class LatticeShare<2>;
template class LatticeShare<3>;
template class LatticeShare<2, 1>;
template class LatticeShare<3, 1>;

}  // namespace mfwave
