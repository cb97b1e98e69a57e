#include "lattice/LatticeSecondOrderSystem.hpp"

#include "core/Error.hpp"

#include <Eigen/LU>

#include <cmath>
#include <map>
#include <string>

namespace mfwave {
namespace {

template <int D>
using Block = Eigen::Matrix<Real, D, D, Eigen::RowMajor>;

// Ding-Long-Wu eq. (32) on the lattice: (M + dt/2 C)^-1 per type, fused with the products; the
// particles with prescribed dofs re-solved on their free dofs afterwards.
template <int D>
class LatticeCentredDamping : public CentredDampingSolve {
 public:
  LatticeCentredDamping(const LatticeSecondOrderSystem<D>& system, Real dt, const std::vector<Index>& prescribedDofs)
      : system_(system), halfStep_(0.5 * dt), inverse_(system.inverseBlocks(0.5 * dt)) {
    const Index n = system.size();
    for (std::size_t i = 0; i < prescribedDofs.size(); ++i) {
      const Index dof = prescribedDofs[i];
      if (dof < 0 || dof >= n)
        throw InputError("prescribed_displacement", "dof " + std::to_string(dof) + " is outside the system's " +
                                                        std::to_string(n) + " unknowns");
      Prescribed& p = particles_[dof / D];
      p.index[dof % D] = static_cast<Index>(i);
    }
  }

  void acceleration(Real t, const Vector& u, const Vector& vHalf, const Vector& prescribedAcceleration,
                    Vector& a) override {
    system_.force(t, a);
    system_.fusedSolve(inverse_, u.data(), vHalf.data(), a.data());
    for (const auto& [particle, prescribed] : particles_) {
      const Index type = system_.types().typeOf(system_.types().node(particle));
      Block<D> matrix = blockOf(system_.mass(), type) + halfStep_ * blockOf(system_.damping(), type);
      Eigen::Matrix<Real, D, 1> solution = Eigen::Map<const Eigen::Matrix<Real, D, 1>>(a.data() + D * particle);
      const Eigen::Matrix<Real, D, 1> rhs = matrix * solution;  // the row's right-hand side, recovered
      std::vector<int> free;
      for (int c = 0; c < D; ++c) {
        if (prescribed.index[c] >= 0) solution[c] = prescribedAcceleration[prescribed.index[c]];
        else free.push_back(c);
      }
      if (!free.empty()) {
        const auto m = static_cast<Index>(free.size());
        Eigen::MatrixXd reduced(m, m);
        Eigen::VectorXd right(m);
        for (Index i = 0; i < m; ++i) {
          right[i] = rhs[free[static_cast<std::size_t>(i)]];
          for (int c = 0; c < D; ++c)
            if (prescribed.index[c] >= 0) right[i] -= matrix(free[static_cast<std::size_t>(i)], c) * solution[c];
          for (Index j = 0; j < m; ++j)
            reduced(i, j) = matrix(free[static_cast<std::size_t>(i)], free[static_cast<std::size_t>(j)]);
        }
        const Eigen::VectorXd x = reduced.partialPivLu().solve(right);
        for (Index i = 0; i < m; ++i) solution[free[static_cast<std::size_t>(i)]] = x[i];
      }
      Eigen::Map<Eigen::Matrix<Real, D, 1>>(a.data() + D * particle) = solution;
    }
  }

 private:
  struct Prescribed {
    Prescribed() { index.fill(-1); }
    std::array<Index, D> index;  // position in the prescribed list, -1 for a free component
  };

  static Block<D> blockOf(const LatticeStencils<D>& table, Index type) {
    Block<D> b = Block<D>::Zero();
    if (!table.empty())
      for (Index e = table.begin(type); e < table.end(type); ++e) b += Eigen::Map<const Block<D>>(table.block(e));
    return b;
  }

  const LatticeSecondOrderSystem<D>& system_;
  Real halfStep_;
  std::vector<Real> inverse_;
  std::map<Index, Prescribed> particles_;
};

}  // namespace

template <int D>
LatticeSecondOrderSystem<D>::LatticeSecondOrderSystem(LatticeStencils<D> mass, LatticeStencils<D> damping,
                                                      LatticeStencils<D> stiffness, ForceFunction force)
    : mass_(std::move(mass)), damping_(std::move(damping)), stiffness_(std::move(stiffness)), force_(std::move(force)) {
  const Index typeCount = stiffness_.typeCount();
  if (mass_.typeCount() != typeCount || mass_.types().nodeCount() != stiffness_.types().nodeCount())
    throw InputError("mass", "the mass stencils are not on the stiffness's lattice");
  if (!mass_.blockDiagonal()) throw InputError("mass", "the lattice system needs a lumped (block-diagonal) mass");
  if (!damping_.empty()) {
    if (damping_.typeCount() != typeCount || damping_.types().nodeCount() != stiffness_.types().nodeCount())
      throw InputError("damping", "the dashpot stencils are not on the stiffness's lattice");
    if (!damping_.blockDiagonal())
      throw InputError("damping", "the lattice system needs dashpots on each particle's own dofs (block-diagonal)");
    hasDamping_ = damping_.entryCount() > 0;
  }
  inverseMass_ = inverseBlocks(0);
}

template <int D>
void LatticeSecondOrderSystem<D>::typeBlock(const LatticeStencils<D>& table, Index type, Real* out) const {
  for (int k = 0; k < D * D; ++k) out[k] = 0;
  if (table.empty()) return;
  for (Index e = table.begin(type); e < table.end(type); ++e)
    for (int k = 0; k < D * D; ++k) out[k] += table.block(e)[k];
}

template <int D>
std::vector<Real> LatticeSecondOrderSystem<D>::inverseBlocks(Real s) const {
  const Index typeCount = stiffness_.typeCount();
  std::vector<Real> inverse(static_cast<std::size_t>(D * D * typeCount));
  for (Index type = 0; type < typeCount; ++type) {
    Block<D> m, c;
    typeBlock(mass_, type, m.data());
    typeBlock(damping_, type, c.data());
    const Block<D> matrix = m + s * c;
    const Real determinant = matrix.determinant();
    if (!(std::abs(determinant) > 0) || !std::isfinite(determinant))
      throw InputError("mass", "the mass" + std::string(s > 0 ? " plus dt/2 times the dashpots" : "") +
                                   " of row type " + std::to_string(type) + " is singular");
    Eigen::Map<Block<D>> target(&inverse[static_cast<std::size_t>(D * D * type)]);
    target = matrix.inverse();
  }
  return inverse;
}

template <int D>
void LatticeSecondOrderSystem<D>::fusedSolve(const std::vector<Real>& inverseBlocks, const Real* u, const Real* v,
                                             Real* a) const {
  const bool damped = hasDamping_ && v != nullptr;
  auto hasDashpot = [&](Index type) { return damped && damping_.begin(type) != damping_.end(type); };
  stiffness_.forEachProduct(
      u,
      [&](Index p, Index type, const Real* ku, Index stride) {
        Real r[D];
        for (int c = 0; c < D; ++c) r[c] = a[D * p + c] - ku[c * stride];
        if (hasDashpot(type)) {
          Real cv[D];
          damping_.rowProduct(type, p, v, cv);
          for (int c = 0; c < D; ++c) r[c] -= cv[c];
        }
        const Real* b = &inverseBlocks[static_cast<std::size_t>(D * D * type)];
        for (int c = 0; c < D; ++c) {
          Real s = 0;
          for (int d = 0; d < D; ++d) s += b[D * c + d] * r[d];
          a[D * p + c] = s;
        }
      },
      hasDashpot);
}

template <int D>
void LatticeSecondOrderSystem<D>::acceleration(Real t, Eigen::Ref<const Vector> u, Eigen::Ref<const Vector> v,
                                               Eigen::Ref<Vector> a) {
  a.setZero();
  if (force_) force_(t, a);
  fusedSolve(inverseMass_, u.data(), v.data(), a.data());
}

template <int D>
void LatticeSecondOrderSystem<D>::force(Real t, Vector& f) const {
  f.setZero(size());
  if (force_) force_(t, f);
}

template <int D>
Real LatticeSecondOrderSystem<D>::kineticEnergy(const Vector& v) const {
  const Real* x = v.data();
  return 0.5 * sumOverLatticeNodes<D>(types(), [&](Index p, Index type) {
    Real mv[D];
    mass_.rowProduct(type, p, x, mv);
    Real s = 0;
    for (int c = 0; c < D; ++c) s += x[D * p + c] * mv[c];
    return s;
  });
}

template <int D>
Real LatticeSecondOrderSystem<D>::strainEnergy(const Vector& u) const {
  // per-line sums, then over lines in order: the same on any thread count
  const Real* x = u.data();
  const Index nx = types().nodes()[0];
  std::vector<Real> lineSums(static_cast<std::size_t>(types().nodeCount() / nx), 0.0);
  stiffness_.forEachProduct(x, [&](Index p, Index, const Real* ku, Index stride) {
    Real s = 0;
    for (int c = 0; c < D; ++c) s += x[D * p + c] * ku[c * stride];
    lineSums[static_cast<std::size_t>(p / nx)] += s;
  });
  Real sum = 0;
  for (Real s : lineSums) sum += s;
  return 0.5 * sum;
}

template <int D>
Real LatticeSecondOrderSystem<D>::dampingPower(const Vector& v) const {
  if (!hasDamping_) return 0;
  const Real* x = v.data();
  return sumOverLatticeNodes<D>(types(), [&](Index p, Index type) {
    if (damping_.begin(type) == damping_.end(type)) return 0.0;
    Real cv[D];
    damping_.rowProduct(type, p, x, cv);
    Real s = 0;
    for (int c = 0; c < D; ++c) s += x[D * p + c] * cv[c];
    return s;
  });
}

template <int D>
Vector LatticeSecondOrderSystem<D>::lumpedMass() const {
  const Index typeCount = mass_.typeCount();
  std::vector<Real> diagonal(static_cast<std::size_t>(D * typeCount));
  for (Index type = 0; type < typeCount; ++type) {
    Real b[D * D];
    typeBlock(mass_, type, b);
    for (int c = 0; c < D; ++c)
      for (int d = 0; d < D; ++d)
        if (c != d && b[D * c + d] != 0) throw InputError("mass", "needs a diagonal (lumped) mass matrix");
    for (int c = 0; c < D; ++c) diagonal[static_cast<std::size_t>(D * type + c)] = b[D * c + c];
  }
  Vector m(size());
  forEachLatticeNode<D>(types(), [&](Index p, Index type) {
    for (int c = 0; c < D; ++c) m[D * p + c] = diagonal[static_cast<std::size_t>(D * type + c)];
  });
  return m;
}

template <int D>
std::unique_ptr<CentredDampingSolve> LatticeSecondOrderSystem<D>::centredDamping(
    Real dt, const std::vector<Index>& prescribedDofs) const {
  return std::make_unique<LatticeCentredDamping<D>>(*this, dt, prescribedDofs);
}

template <int D>
std::size_t LatticeSecondOrderSystem<D>::bytes() const {
  return mass_.bytes() + damping_.bytes() + stiffness_.bytes() + inverseMass_.size() * sizeof(Real);
}

template class LatticeSecondOrderSystem<1>;
template class LatticeSecondOrderSystem<2>;
template class LatticeSecondOrderSystem<3>;

}  // namespace mfwave
