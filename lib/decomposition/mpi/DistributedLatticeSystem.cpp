#include "decomposition/mpi/DistributedLatticeSystem.hpp"

#include "core/Error.hpp"
#include "decomposition/mpi/LineSums.hpp"

#include <string>

namespace mfwave {

template <int D>
DistributedLatticeSystem<D>::DistributedLatticeSystem(const LatticeSecondOrderSystem<D>& serial,
                                                      const BlockDecomposition<D>& decomposition, int rank,
                                                      MPI_Comm communicator)
    : serial_(serial), decomposition_(decomposition), rank_(rank), communicator_(communicator) {
  if (serial.hasDamping())
    throw InputError("damping", "the distributed lattice system does not take dashpots yet (docs/scaling.md)");
  if (serial.hasForce())
    throw InputError("loads", "the distributed lattice system does not take loads yet (docs/scaling.md)");
  if (decomposition.grid()[0] != 1)
    throw InputError("ranks", "the decomposition splits x into " + std::to_string(decomposition.grid()[0]) +
                                  " blocks; the distributed system needs whole lattice lines per rank");
  exchange_ = std::make_unique<HaloExchange<D>>(HaloPlan<D>(decomposition, rank, stencilReach(serial.stiffness())), D,
                                                communicator);
  stiffness_ = std::make_unique<LocalStencils<D>>(serial.stiffness(), exchange_->plan().owned(), exchange_->plan().local());
  inverseMass_ = serial.inverseBlocks(0);
  massFlat_.assign(static_cast<std::size_t>(serial.mass().entryCount()), 0);
  local_.resize(static_cast<std::size_t>(exchange_->localSize()));
  ku_.resize(static_cast<std::size_t>(size()));
}

template <int D>
void DistributedLatticeSystem<D>::applyStiffness(const Real* u) {
  const Box<D>& own = owned();
  const Box<D>& local = exchange_->plan().local();
  own.forEachNode([&](const std::array<Index, D>& node) {
    const Real* from = u + D * own.localIndex(node);
    Real* to = local_.data() + D * local.localIndex(node);
    for (int c = 0; c < D; ++c) to[c] = from[c];
  });
  exchange_->exchange(local_.data());
  stiffness_->multiply(local_.data(), ku_.data());
}

template <int D>
void DistributedLatticeSystem<D>::acceleration(Real, Eigen::Ref<const Vector> u, Eigen::Ref<const Vector>,
                                               Eigen::Ref<Vector> a) {
  applyStiffness(u.data());
  const LatticeRowTypes<D>& types = serial_.types();
  const Box<D>& own = owned();
  own.forEachNode([&](const std::array<Index, D>& node) {
    const Index k = own.localIndex(node);
    // LatticeSecondOrderSystem::fusedSolve with a = 0 (no loads): r = a - K u, a = M^-1 r.
    Real r[D];
    for (int c = 0; c < D; ++c) r[c] = 0.0 - ku_[static_cast<std::size_t>(D * k + c)];
    const Real* b = &inverseMass_[static_cast<std::size_t>(D * D * types.typeOf(node))];
    for (int c = 0; c < D; ++c) {
      Real s = 0;
      for (int d = 0; d < D; ++d) s += b[D * c + d] * r[d];
      a[D * k + c] = s;
    }
  });
}

template <int D>
Real DistributedLatticeSystem<D>::kineticEnergy(const Vector& v) const {
  // LatticeSecondOrderSystem::kineticEnergy: v . M v per node (row by row), summed per line.
  const Box<D>& own = owned();
  const LatticeRowTypes<D>& types = serial_.types();
  const Index nx = own.extent(0);
  std::vector<Real> lineSums(static_cast<std::size_t>(own.count() / nx), 0.0);
  own.forEachNode([&](const std::array<Index, D>& node) {
    const Index k = own.localIndex(node);
    Real mv[D];
    serial_.mass().rowProductAt(types.typeOf(node), v.data() + D * k, massFlat_.data(), mv);
    Real s = 0;
    for (int c = 0; c < D; ++c) s += v[D * k + c] * mv[c];
    lineSums[static_cast<std::size_t>(k / nx)] += s;
  });
  return 0.5 * sumInLatticeOrder(decomposition_, rank_, lineSums, communicator_);
}

template <int D>
Real DistributedLatticeSystem<D>::strainEnergy(const Vector& u) {
  // LatticeSecondOrderSystem::strainEnergy: u . K u per node, summed per line.
  applyStiffness(u.data());
  const Box<D>& own = owned();
  const Index nx = own.extent(0);
  std::vector<Real> lineSums(static_cast<std::size_t>(own.count() / nx), 0.0);
  own.forEachNode([&](const std::array<Index, D>& node) {
    const Index k = own.localIndex(node);
    Real s = 0;
    for (int c = 0; c < D; ++c) s += u[D * k + c] * ku_[static_cast<std::size_t>(D * k + c)];
    lineSums[static_cast<std::size_t>(k / nx)] += s;
  });
  return 0.5 * sumInLatticeOrder(decomposition_, rank_, lineSums, communicator_);
}

template <int D>
Vector DistributedLatticeSystem<D>::restrict(const Vector& whole) const {
  Box<D> all;
  all.hi = serial_.types().nodes();
  Vector part(size());
  owned().forEachNode([&](const std::array<Index, D>& node) {
    for (int c = 0; c < D; ++c) part[D * owned().localIndex(node) + c] = whole[D * all.localIndex(node) + c];
  });
  return part;
}

template class DistributedLatticeSystem<1>;
template class DistributedLatticeSystem<2>;
template class DistributedLatticeSystem<3>;

}  // namespace mfwave
