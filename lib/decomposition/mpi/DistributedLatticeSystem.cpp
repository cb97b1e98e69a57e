#include "decomposition/mpi/DistributedLatticeSystem.hpp"

#include "core/Error.hpp"
#include "decomposition/mpi/LineSums.hpp"
#include "lattice/DashpotSurfaceSolve.hpp"
#include "lattice/PrescribedNodeSolve.hpp"
#include "integrators/ArkodeMpiVectors.hpp"

#include <algorithm>
#include <string>

namespace mfwave {

namespace {

// Ding-Long-Wu eq. (32) on one rank's nodes: the per-type inverse blocks of M + dt/2 C, applied by
// DistributedLatticeSystem::solve, then the rank's prescribed nodes (eq. (30), PrescribedNodeSolve)
// as the serial LatticeCentredDamping does them.
template <int D, int C>
class DistributedCentredDamping : public CentredDampingSolve {
 public:
  DistributedCentredDamping(const DistributedLatticeSystem<D, C>& system, const LatticeSecondOrderSystem<D, C>& serial,
                            Real dt, const std::vector<Index>& prescribedDofs)
      : system_(system), serial_(serial), halfStep_(0.5 * dt), inverse_(serial.inverseBlocks(0.5 * dt)),
        prescribed_(prescribedDofs, system.size()) {}

  void acceleration(Real t, const Vector& u, const Vector& vHalf, const Vector& prescribedAcceleration,
                    Vector& a) override {
    a.resize(system_.size());
    system_.solve(inverse_, t, u.data(), vHalf.data(), a.data());
    if (prescribed_.empty()) return;
    const Box<D>& owned = system_.owned();
    const LatticeRowTypes<D>& types = serial_.types();
    prescribed_.apply(serial_.mass(), serial_.damping(), halfStep_,
                      [&](Index local) { return types.typeOf(owned.node(local)); }, prescribedAcceleration,
                      a.data());
  }

 private:
  const DistributedLatticeSystem<D, C>& system_;
  const LatticeSecondOrderSystem<D, C>& serial_;
  Real halfStep_;
  std::vector<Real> inverse_;
  PrescribedNodeSolve<D, C> prescribed_;
};

// Eq. (32) with dashpots that couple nodes: every rank holds the same factorisation of the dashpot
// block (DashpotSurfaceSolve, the surface's size), gathers the block's right-hand side from the
// owners (the -0.0 of the others adds nothing, as in RankProbes) and solves it whole, so each
// rank's share of the solution is the serial one bit for bit. The block is replicated: a surface of
// s^2 nodes costs every rank its factorisation and an all-reduce of 3 s^2 values per step, fine to
// about 10^7 particles (docs/scaling.md).
template <int D, int C>
class DistributedCoupledCentredDamping : public CentredDampingSolve {
 public:
  DistributedCoupledCentredDamping(const DistributedLatticeSystem<D, C>& system, const LatticeSecondOrderSystem<D, C>& serial,
                                   Real dt, MPI_Comm communicator)
      : system_(system), serial_(serial), inverseMass_(serial.inverseBlocks(0)), surface_(serial, dt, {}),
        communicator_(communicator) {
    for (Index node : surface_.nodes()) local_.push_back(system.localNode(node));
    rhs_.resize(C * static_cast<Index>(local_.size()));
    solution_.resize(rhs_.size());
  }

  void acceleration(Real t, const Vector& u, const Vector& vHalf, const Vector&, Vector& a) override {
    a.resize(system_.size());
    system_.solve(inverseMass_, t, u.data(), vHalf.data(), a.data());
    for (std::size_t k = 0; k < local_.size(); ++k) {
      Real* rhs = rhs_.data() + C * static_cast<Index>(k);
      if (local_[k] >= 0) surface_.massTimes(serial_, k, a.data() + C * local_[k], rhs);
      else std::fill(rhs, rhs + C, -0.0);
    }
    MPI_Allreduce(MPI_IN_PLACE, rhs_.data(), static_cast<int>(rhs_.size()), MPI_DOUBLE, MPI_SUM, communicator_);
    surface_.solve(rhs_, solution_);
    for (std::size_t k = 0; k < local_.size(); ++k)
      if (local_[k] >= 0)
        for (int c = 0; c < C; ++c) a[C * local_[k] + c] = solution_[C * static_cast<Index>(k) + c];
  }

 private:
  const DistributedLatticeSystem<D, C>& system_;
  const LatticeSecondOrderSystem<D, C>& serial_;
  std::vector<Real> inverseMass_;
  DashpotSurfaceSolve<D, C> surface_;
  MPI_Comm communicator_;
  std::vector<Index> local_;  // per block node: its place in this rank's state, or -1
  Vector rhs_, solution_;
};

}  // namespace

template <int D, int C>
DistributedLatticeSystem<D, C>::DistributedLatticeSystem(const LatticeSecondOrderSystem<D, C>& serial,
                                                      const BlockDecomposition<D>& decomposition, int rank,
                                                      MPI_Comm communicator)
    : serial_(serial), decomposition_(decomposition), rank_(rank), communicator_(communicator) {
  if (serial.hasForce() && !serial.sparseLoads())
    throw InputError("loads", "the distributed lattice system needs its loads as nonzero entries (SparseLoads), not "
                              "as a function of the whole lattice's vector");
  stiffness_ = std::make_unique<RankStencilProduct<D, C>>(serial.stiffness(), decomposition, rank, communicator);
  if (serial.hasDamping() && !serial.damping().blockDiagonal()) {
    // C v reads the neighbours' velocities: its own halo, every row by itself as the serial
    // rowProduct computes it.
    damping_ = std::make_unique<RankStencilProduct<D, C>>(serial.damping(), decomposition, rank, communicator);
    allRowByRow_.assign(static_cast<std::size_t>(serial.damping().typeCount()), 1);
    cv_.resize(static_cast<std::size_t>(size()));
  }
  inverseMass_ = serial.inverseBlocks(0);
  nodeFlat_.assign(static_cast<std::size_t>(std::max(serial.mass().entryCount(), serial.damping().entryCount())), 0);
  for (Index type = 0; type < serial.stiffness().typeCount(); ++type)
    dashpotTypes_.push_back(serial.hasDamping() && serial.damping().begin(type) != serial.damping().end(type));
  // The loads' owned entries, in their serial order: each owned dof receives the same additions.
  if (const std::vector<SparseLoad>* loads = serial.sparseLoads()) {
    const LatticeRowTypes<D>& types = serial.types();
    for (const SparseLoad& load : *loads) {
      SparseLoad mine;
      mine.history = load.history;
      for (std::size_t k = 0; k < load.dofs.size(); ++k) {
        const std::array<Index, D> node = types.node(load.dofs[k] / C);
        if (!owned().contains(node)) continue;
        mine.dofs.push_back(C * owned().localIndex(node) + load.dofs[k] % C);
        mine.values.push_back(load.values[k]);
      }
      loads_.push_back(std::move(mine));
    }
  }
  // Summed rather than taken from the serial system: the ranks' shares must cover it exactly,
  // and N_VMake_Parallel checks the same sum again.
  long long total = static_cast<long long>(size());
  MPI_Allreduce(MPI_IN_PLACE, &total, 1, MPI_LONG_LONG, MPI_SUM, communicator);
  globalSize_ = static_cast<Index>(total);
  // Any ARKODE integrator handed this system works on the MPI vectors (distribution()).
  enableArkodeMpiVectors();
}

template <int D, int C>
void DistributedLatticeSystem<D, C>::solve(const std::vector<Real>& inverseBlocks, Real t, const Real* u, const Real* v,
                                        Real* a) const {
  std::fill(a, a + size(), 0.0);
  addSparseLoads(loads_, t, a);
  const bool damped = serial_.hasDamping() && v != nullptr;
  const LatticeStencils<D, C>& damping = serial_.damping();
  if (damped && damping_) damping_->multiply(v, cv_.data(), &allRowByRow_);
  // LatticeSecondOrderSystem::fusedSolve, fused with the product as it is: r = f - K u - C v,
  // a = B r; the dashpot types row by row.
  stiffness_->forEachProduct(u, [&](Index k, Index type, const Real* ku, Index stride) {
    Real r[C];
    for (int c = 0; c < C; ++c) r[c] = a[C * k + c] - ku[c * stride];
    if (damped && damping.begin(type) != damping.end(type)) {
      Real own[C];
      const Real* cv = own;
      if (damping_) cv = cv_.data() + C * k;
      else damping.rowProductAt(type, v + C * k, nodeFlat_.data(), own);
      for (int c = 0; c < C; ++c) r[c] -= cv[c];
    }
    const Real* b = &inverseBlocks[static_cast<std::size_t>(C * C * type)];
    for (int c = 0; c < C; ++c) {
      Real s = 0;
      for (int d = 0; d < C; ++d) s += b[C * c + d] * r[d];
      a[C * k + c] = s;
    }
  }, [&](Index type) { return damped && dashpotTypes_[static_cast<std::size_t>(type)]; });
}

template <int D, int C>
void DistributedLatticeSystem<D, C>::acceleration(Real t, Eigen::Ref<const Vector> u, Eigen::Ref<const Vector> v,
                                               Eigen::Ref<Vector> a) {
  solve(inverseMass_, t, u.data(), v.size() == size() ? v.data() : nullptr, a.data());
}

template <int D, int C>
void DistributedLatticeSystem<D, C>::force(Real t, Vector& f) const {
  f.setZero(size());
  addSparseLoads(loads_, t, f.data());
}

template <int D, int C>
void DistributedLatticeSystem<D, C>::applyStiffness(const Vector& x, Vector& y) const {
  y.resize(size());
  stiffness_->multiply(x.data(), y.data());
}

template <int D, int C>
template <class Function>
void DistributedLatticeSystem<D, C>::forEachOwnedNode(Function&& f) const {
  // Line by line (an owned line is a whole lattice line, or its x-piece when x is split), its row
  // types from the line's base type as forEachLatticeLine gives them (the base taken at the owned
  // line's first node, wherever it starts); threads share lines in a fixed partition.
  const Box<D>& own = owned();
  const LatticeRowTypes<D>& types = serial_.types();
  const Index nx = own.extent(0);
  const long lines = static_cast<long>(own.lineCount());
#pragma omp parallel for schedule(static) if (lines > 16 && own.count() > 20000)
  for (long line = 0; line < lines; ++line) {
    const std::array<Index, D> start = own.lineStart(line);
    const Index first = static_cast<Index>(line) * nx;
    const Index base = types.typeOf(start) - types.compactIndex(0, start[0]);
    for (Index i = 0; i < nx; ++i) f(first + i, base + types.compactIndex(0, start[0] + i));
  }
}

template <int D, int C>
template <class Function>
Real DistributedLatticeSystem<D, C>::sumOverOwnedNodes(Function&& g) const {
  // One term per node, line by line along x in node order, as sumOverLatticeNodes adds them; the
  // x-pieces of a line and the lines over the ranks in the lattice's order (LineSums.hpp).
  return sumInLatticeOrder<D>(decomposition_, rank_, 1, [&](auto&& add) {
    forEachOwnedNode([&](Index k, Index type) { add(k, 0, g(k, type)); });
  }, communicator_);
}

template <int D, int C>
Real DistributedLatticeSystem<D, C>::kineticEnergy(const Vector& v) const {
  return 0.5 * sumOverOwnedNodes([&](Index k, Index type) {
           Real mv[C];
           serial_.mass().rowProductAt(type, v.data() + C * k, nodeFlat_.data(), mv);
           Real s = 0;
           for (int c = 0; c < C; ++c) s += v[C * k + c] * mv[c];
           return s;
         });
}

template <int D, int C>
Real DistributedLatticeSystem<D, C>::strainEnergy(const Vector& u) const {
  // As LatticeSecondOrderSystem::strainEnergy: u . K u per node from the products, per line. The
  // products (a collective halo exchange) are all taken before the x-pieces wait on one another.
  return 0.5 * sumInLatticeOrder<D>(decomposition_, rank_, 1, [&](auto&& add) {
    stiffness_->forEachProduct(u.data(), [&](Index k, Index, const Real* ku, Index stride) {
      Real s = 0;
      for (int c = 0; c < C; ++c) s += u[C * k + c] * ku[c * stride];
      add(k, 0, s);
    }, [](Index) { return false; });
  }, communicator_);
}

template <int D, int C>
Real DistributedLatticeSystem<D, C>::dampingPower(const Vector& v) const {
  if (!serial_.hasDamping()) return 0;
  // The serial sum adds only the nodes with dashpots; the others add nothing here either (a line
  // without dashpots sums to +0 in both).
  const LatticeStencils<D, C>& damping = serial_.damping();
  if (damping_) damping_->multiply(v.data(), cv_.data(), &allRowByRow_);
  // The serial sum adds each component's term to the line's sum: C terms per node.
  return sumInLatticeOrder<D>(decomposition_, rank_, C, [&](auto&& add) {
    forEachOwnedNode([&](Index k, Index type) {
      if (damping.begin(type) == damping.end(type)) return;
      Real own[C];
      const Real* cv = own;
      if (damping_) cv = cv_.data() + C * k;
      else damping.rowProductAt(type, v.data() + C * k, nodeFlat_.data(), own);
      for (int c = 0; c < C; ++c) add(k, c, v[C * k + c] * cv[c]);
    });
  }, communicator_);
}

template <int D, int C>
std::optional<VectorDistribution> DistributedLatticeSystem<D, C>::distribution() const {
  VectorDistribution d{&communicator_, globalSize_, {}};
  d.orderedSumOfSquares = [this](const Real* z, Index count) {
    const Vector values = Eigen::Map<const Vector>(z, count);
    return dot(values, values);
  };
  return d;
}

template <int D, int C>
Real DistributedLatticeSystem<D, C>::dot(const Vector& a, const Vector& b) const {
  return sumOverOwnedNodes([&](Index k, Index) {
    Real s = 0;
    for (int c = 0; c < C; ++c) s += a[C * k + c] * b[C * k + c];
    return s;
  });
}

template <int D, int C>
Vector DistributedLatticeSystem<D, C>::lumpedMass() const {
  const std::vector<Real> perType = serial_.lumpedMassPerType();
  Vector m(size());
  forEachOwnedNode([&](Index k, Index type) {
    for (int c = 0; c < C; ++c) m[C * k + c] = perType[static_cast<std::size_t>(C * type + c)];
  });
  return m;
}

template <int D, int C>
Vector DistributedLatticeSystem<D, C>::stiffnessAbsoluteRowSums() const {
  const std::vector<Real> perType = serial_.stiffness().absoluteRowSumsPerType();
  Vector sums(size());
  forEachOwnedNode([&](Index k, Index type) {
    for (int c = 0; c < C; ++c) sums[C * k + c] = perType[static_cast<std::size_t>(C * type + c)];
  });
  return sums;
}

template <int D, int C>
Real DistributedLatticeSystem<D, C>::maximum(Real value) const {
  MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_DOUBLE, MPI_MAX, communicator_);
  return value;
}

template <int D, int C>
void DistributedLatticeSystem<D, C>::fillByGlobalIndex(Vector& x, const std::function<Real(Index)>& value) const {
  Box<D> all;
  all.hi = serial_.types().nodes();
  x.resize(size());
  owned().forEachNode([&](const std::array<Index, D>& node) {
    const Index k = owned().localIndex(node), global = all.localIndex(node);
    for (int c = 0; c < C; ++c) x[C * k + c] = value(C * global + c);
  });
}

template <int D, int C>
std::unique_ptr<CentredDampingSolve> DistributedLatticeSystem<D, C>::centredDamping(
    Real dt, const std::vector<Index>& prescribedDofs) const {
  if (damping_ && !prescribedDofs.empty())
    throw InputError("prescribed_displacement",
                     "the distributed lattice system does not take prescribed displacements beside dashpots that "
                     "couple nodes yet (docs/scaling.md)");
  if (damping_) return std::make_unique<DistributedCoupledCentredDamping<D, C>>(*this, serial_, dt, communicator_);
  return std::make_unique<DistributedCentredDamping<D, C>>(*this, serial_, dt, prescribedDofs);
}

template <int D, int C>
Index DistributedLatticeSystem<D, C>::localNode(Index latticeNode) const {
  const std::array<Index, D> node = serial_.types().node(latticeNode);
  return owned().contains(node) ? owned().localIndex(node) : -1;
}

template <int D, int C>
Vector DistributedLatticeSystem<D, C>::restrict(const Vector& whole) const {
  Box<D> all;
  all.hi = serial_.types().nodes();
  Vector part(size());
  owned().forEachNode([&](const std::array<Index, D>& node) {
    for (int c = 0; c < C; ++c) part[C * owned().localIndex(node) + c] = whole[C * all.localIndex(node) + c];
  });
  return part;
}

template class DistributedLatticeSystem<1>;
template class DistributedLatticeSystem<2>;
template class DistributedLatticeSystem<3>;
template class DistributedLatticeSystem<2, 1>;
template class DistributedLatticeSystem<3, 1>;

}  // namespace mfwave
