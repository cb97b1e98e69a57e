#include "lattice/LatticeSecondOrderSystem.hpp"

#include "lattice/DashpotSurfaceSolve.hpp"
#include "lattice/PrescribedNodeSolve.hpp"

#include "core/Error.hpp"
#include "solvers/FactorisedMatrix.hpp"

#include <Eigen/LU>

#include <cmath>
#include <algorithm>
#include <map>
#include <string>

namespace mfwave {
namespace {

template <int C>
using Block = Eigen::Matrix<Real, C, C, Eigen::RowMajor>;

// Ding-Long-Wu eq. (32) on the lattice: (M + dt/2 C)^-1 per type, fused with the products; the
// particles with prescribed dofs re-solved on their free dofs afterwards.
template <int D, int C>
class LatticeCentredDamping : public CentredDampingSolve {
 public:
  LatticeCentredDamping(const LatticeSecondOrderSystem<D, C>& system, Real dt, const std::vector<Index>& prescribedDofs)
      : system_(system), halfStep_(0.5 * dt), inverse_(system.inverseBlocks(0.5 * dt)),
        prescribed_(prescribedDofs, system.size()) {}

  void acceleration(Real t, const Vector& u, const Vector& vHalf, const Vector& prescribedAcceleration,
                    Vector& a) override {
    system_.force(t, a);
    system_.fusedSolve(inverse_, u.data(), vHalf.data(), a.data());
    const LatticeRowTypes<D>& types = system_.types();
    prescribed_.apply(system_.mass(), system_.damping(), halfStep_,
                      [&types](Index node) { return types.typeOf(types.node(node)); }, prescribedAcceleration,
                      a.data());
  }

 private:
  const LatticeSecondOrderSystem<D, C>& system_;
  Real halfStep_;
  std::vector<Real> inverse_;
  PrescribedNodeSolve<D, C> prescribed_;
};

// Eq. (32) with dashpots that couple particles (DashpotSurfaceSolve): M^-1 (f - K u - C v) at every
// node, then on the nodes the dashpots reach M times that is the right-hand side of the block's
// solve; prescribed dofs away from the dashpots take their accelerations (a lumped mass does not
// couple them).
template <int D, int C>
class LatticeCoupledCentredDamping : public CentredDampingSolve {
 public:
  LatticeCoupledCentredDamping(const LatticeSecondOrderSystem<D, C>& system, Real dt, const std::vector<Index>& prescribedDofs)
      : system_(system), inverseMass_(system.inverseBlocks(0)), surface_(system, dt, prescribedDofs) {
    rhs_.resize(C * static_cast<Index>(surface_.nodes().size()));
    solution_.resize(rhs_.size());
  }

  void acceleration(Real t, const Vector& u, const Vector& vHalf, const Vector& prescribedAcceleration,
                    Vector& a) override {
    system_.force(t, a);
    system_.fusedSolve(inverseMass_, u.data(), vHalf.data(), a.data());
    const std::vector<Index>& nodes = surface_.nodes();
    for (std::size_t k = 0; k < nodes.size(); ++k)
      surface_.massTimes(system_, k, a.data() + C * nodes[k], rhs_.data() + C * static_cast<Index>(k));
    for (const auto& [row, i] : surface_.inside()) rhs_[row] = prescribedAcceleration[i];
    surface_.solve(rhs_, solution_);
    for (std::size_t k = 0; k < nodes.size(); ++k)
      for (int c = 0; c < C; ++c) a[C * nodes[k] + c] = solution_[C * static_cast<Index>(k) + c];
    for (const auto& [dof, i] : surface_.outside()) a[dof] = prescribedAcceleration[i];
  }

 private:
  const LatticeSecondOrderSystem<D, C>& system_;
  std::vector<Real> inverseMass_;
  DashpotSurfaceSolve<D, C> surface_;
  Vector rhs_, solution_;
};

}  // namespace

template <int D, int C>
LatticeSecondOrderSystem<D, C>::LatticeSecondOrderSystem(LatticeStencils<D, C> mass, LatticeStencils<D, C> damping,
                                                      LatticeStencils<D, C> stiffness, ForceFunction force)
    : mass_(std::move(mass)), damping_(std::move(damping)), stiffness_(std::move(stiffness)), force_(std::move(force)) {
  const Index typeCount = stiffness_.typeCount();
  if (mass_.typeCount() != typeCount || mass_.types().nodeCount() != stiffness_.types().nodeCount())
    throw InputError("mass", "the mass stencils are not on the stiffness's lattice");
  if (!mass_.blockDiagonal()) throw InputError("mass", "the lattice system needs a lumped (block-diagonal) mass");
  if (!damping_.empty()) {
    if (damping_.typeCount() != typeCount || damping_.types().nodeCount() != stiffness_.types().nodeCount())
      throw InputError("damping", "the dashpot stencils are not on the stiffness's lattice");
    hasDamping_ = damping_.entryCount() > 0;
  }
  inverseMass_ = inverseBlocks(0);
}

template <int D, int C>
LatticeSecondOrderSystem<D, C>::LatticeSecondOrderSystem(LatticeStencils<D, C> mass, LatticeStencils<D, C> damping,
                                                      LatticeStencils<D, C> stiffness, std::vector<SparseLoad> loads)
    : LatticeSecondOrderSystem(std::move(mass), std::move(damping), std::move(stiffness)) {
  if (loads.empty()) return;
  for (const SparseLoad& load : loads)
    for (Index dof : load.dofs)
      if (dof < 0 || dof >= size())
        throw InputError("loads", "dof " + std::to_string(dof) + " is outside the system's " + std::to_string(size()) +
                                      " unknowns");
  loads_ = std::make_shared<const std::vector<SparseLoad>>(std::move(loads));
  force_ = [loads = loads_](Real t, Eigen::Ref<Vector> f) { addSparseLoads(*loads, t, f.data()); };
}

template <int D, int C>
std::vector<Real> LatticeSecondOrderSystem<D, C>::inverseBlocks(Real s) const {
  const Index typeCount = stiffness_.typeCount();
  std::vector<Real> inverse(static_cast<std::size_t>(C * C * typeCount));
  for (Index type = 0; type < typeCount; ++type) {
    Block<C> m, c;
    mass_.typeSum(type, m.data());
    damping_.typeSum(type, c.data());
    const Block<C> matrix = m + s * c;
    const Real determinant = matrix.determinant();
    if (!(std::abs(determinant) > 0) || !std::isfinite(determinant))
      throw InputError("mass", "the mass" + std::string(s > 0 ? " plus dt/2 times the dashpots" : "") +
                                   " of row type " + std::to_string(type) + " is singular");
    Eigen::Map<Block<C>> target(&inverse[static_cast<std::size_t>(C * C * type)]);
    target = matrix.inverse();
  }
  return inverse;
}

template <int D, int C>
void LatticeSecondOrderSystem<D, C>::fusedSolve(const std::vector<Real>& inverseBlocks, const Real* u, const Real* v,
                                             Real* a) const {
  const bool damped = hasDamping_ && v != nullptr;
  auto hasDashpot = [&](Index type) { return damped && damping_.begin(type) != damping_.end(type); };
  stiffness_.forEachProduct(
      u,
      [&](Index p, Index type, const Real* ku, Index stride) {
        Real r[C];
        for (int c = 0; c < C; ++c) r[c] = a[C * p + c] - ku[c * stride];
        if (hasDashpot(type)) {
          Real cv[C];
          damping_.rowProduct(type, p, v, cv);
          for (int c = 0; c < C; ++c) r[c] -= cv[c];
        }
        const Real* b = &inverseBlocks[static_cast<std::size_t>(C * C * type)];
        for (int c = 0; c < C; ++c) {
          Real s = 0;
          for (int d = 0; d < C; ++d) s += b[C * c + d] * r[d];
          a[C * p + c] = s;
        }
      },
      hasDashpot);
}

template <int D, int C>
void LatticeSecondOrderSystem<D, C>::acceleration(Real t, Eigen::Ref<const Vector> u, Eigen::Ref<const Vector> v,
                                               Eigen::Ref<Vector> a) {
  a.setZero();
  if (force_) force_(t, a);
  fusedSolve(inverseMass_, u.data(), v.data(), a.data());
}

template <int D, int C>
void LatticeSecondOrderSystem<D, C>::force(Real t, Vector& f) const {
  f.setZero(size());
  if (force_) force_(t, f);
}

template <int D, int C>
Real LatticeSecondOrderSystem<D, C>::kineticEnergy(const Vector& v) const {
  const Real* x = v.data();
  return 0.5 * sumOverLatticeNodes<D>(types(), [&](Index p, Index type) {
    Real mv[C];
    mass_.rowProduct(type, p, x, mv);
    Real s = 0;
    for (int c = 0; c < C; ++c) s += x[C * p + c] * mv[c];
    return s;
  });
}

template <int D, int C>
Real LatticeSecondOrderSystem<D, C>::strainEnergy(const Vector& u) const {
  // per-line sums, then over lines in order: the same on any thread count
  const Real* x = u.data();
  const Index nx = types().nodes()[0];
  std::vector<Real> lineSums(static_cast<std::size_t>(types().nodeCount() / nx), 0.0);
  stiffness_.forEachProduct(x, [&](Index p, Index, const Real* ku, Index stride) {
    Real s = 0;
    for (int c = 0; c < C; ++c) s += x[C * p + c] * ku[c * stride];
    lineSums[static_cast<std::size_t>(p / nx)] += s;
  });
  Real sum = 0;
  for (Real s : lineSums) sum += s;
  return 0.5 * sum;
}

template <int D, int C>
Real LatticeSecondOrderSystem<D, C>::dot(const Vector& a, const Vector& b) const {
  return sumOverLatticeNodes<D>(types(), [&](Index p, Index) {
    Real s = 0;
    for (int c = 0; c < C; ++c) s += a[C * p + c] * b[C * p + c];
    return s;
  });
}

template <int D, int C>
std::optional<VectorDistribution> LatticeSecondOrderSystem<D, C>::distribution() const {
  VectorDistribution d;
  d.globalSize = size();
  d.orderedSumOfSquares = [this](const Real* z, Index count) {
    const Vector values = Eigen::Map<const Vector>(z, count);
    return dot(values, values);
  };
  return d;
}

template <int D, int C>
Real LatticeSecondOrderSystem<D, C>::dampingPower(const Vector& v) const {
  if (!hasDamping_) return 0;
  // Line by line, visiting only the nodes whose type has dashpots (the surface): per-line sums,
  // then over lines in order, the same on any thread count.
  const Real* x = v.data();
  const LatticeRowTypes<D>& t = types();
  const Index nx = t.nodes()[0];
  std::vector<Real> lineSums(static_cast<std::size_t>(t.nodeCount() / nx), 0.0);
  forEachLatticeLine<D>(t, [&](Index first, Index base) {
    Real sum = 0;
    auto node = [&](Index i) {
      const Index type = base + t.compactIndex(0, i);
      if (damping_.begin(type) == damping_.end(type)) return;
      Real cv[C];
      damping_.rowProduct(type, first + i, x, cv);
      for (int c = 0; c < C; ++c) sum += x[C * (first + i) + c] * cv[c];
    };
    const Index depth = t.depth();
    const bool middle = t.compactNodes()[0] < nx;
    if (!middle) {
      for (Index i = 0; i < nx; ++i) node(i);
    } else {
      for (Index i = 0; i < depth; ++i) node(i);
      const Index type = base + depth;
      if (damping_.begin(type) != damping_.end(type))
        for (Index i = depth; i < nx - depth; ++i) node(i);
      for (Index i = nx - depth; i < nx; ++i) node(i);
    }
    lineSums[static_cast<std::size_t>(first / nx)] = sum;
  });
  Real total = 0;
  for (Real s : lineSums) total += s;
  return total;
}

template <int D, int C>
std::vector<Real> LatticeSecondOrderSystem<D, C>::lumpedMassPerType() const {
  const Index typeCount = mass_.typeCount();
  std::vector<Real> diagonal(static_cast<std::size_t>(C * typeCount));
  for (Index type = 0; type < typeCount; ++type) {
    Real b[C * C];
    mass_.typeSum(type, b);
    for (int c = 0; c < C; ++c)
      for (int d = 0; d < C; ++d)
        if (c != d && b[C * c + d] != 0) throw InputError("mass", "needs a diagonal (lumped) mass matrix");
    for (int c = 0; c < C; ++c) diagonal[static_cast<std::size_t>(C * type + c)] = b[C * c + c];
  }
  return diagonal;
}

template <int D, int C>
Vector LatticeSecondOrderSystem<D, C>::lumpedMass() const {
  const std::vector<Real> diagonal = lumpedMassPerType();
  Vector m(size());
  forEachLatticeNode<D>(types(), [&](Index p, Index type) {
    for (int c = 0; c < C; ++c) m[C * p + c] = diagonal[static_cast<std::size_t>(C * type + c)];
  });
  return m;
}

template <int D, int C>
std::unique_ptr<CentredDampingSolve> LatticeSecondOrderSystem<D, C>::centredDamping(
    Real dt, const std::vector<Index>& prescribedDofs) const {
  if (!damping_.empty() && !damping_.blockDiagonal())
    return std::make_unique<LatticeCoupledCentredDamping<D, C>>(*this, dt, prescribedDofs);
  return std::make_unique<LatticeCentredDamping<D, C>>(*this, dt, prescribedDofs);
}

template <int D, int C>
std::size_t LatticeSecondOrderSystem<D, C>::bytes() const {
  return mass_.bytes() + damping_.bytes() + stiffness_.bytes() + inverseMass_.size() * sizeof(Real);
}

template class LatticeSecondOrderSystem<1>;
template class LatticeSecondOrderSystem<2>;
template class LatticeSecondOrderSystem<3>;
template class LatticeSecondOrderSystem<2, 1>;
template class LatticeSecondOrderSystem<3, 1>;

}  // namespace mfwave
