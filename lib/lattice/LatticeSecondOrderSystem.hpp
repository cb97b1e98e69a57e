#pragma once
// M u'' + C u' + K u = f(t) on a box lattice from per-row-type stencils (LatticeStencils): K and C
// any stencils, M block-diagonal (lumped). Per particle it stores nothing: the acceleration, the
// dashpot solve of central difference (Ding-Long-Wu eq. (32)) and the energies are fused passes
// over the lattice, with the inverses of M and, for dashpots on each particle's own dofs, of
// M + dt/2 C kept per type. Dashpots that couple particles get M + dt/2 C factorised on the nodes
// they reach (a few layers under the faces), so the solve stays proportional to the surface.
// Results are bitwise the same on any thread count.
//
// The matrix-free counterpart of LinearSecondOrderSystem on lattices (issue 18): the same rows, a
// few hundred stencils instead of a sparse matrix of N x neighbours entries.

#include "lattice/LatticeStencils.hpp"
#include "systems/LinearOperatorSystem.hpp"
#include "systems/SparseLoads.hpp"

#include <functional>
#include <memory>

namespace mfwave {

// C unknowns per node: C = D for displacements, C = 1 for a scalar field (the finite-difference wave).
template <int D, int C = D>
class LatticeSecondOrderSystem : public LinearOperatorSystem {
 public:
  // Adds f(t) into f (which the system has zeroed).
  using ForceFunction = std::function<void(Real t, Eigen::Ref<Vector> f)>;

  // All three on the same lattice; damping may be empty (no dashpots). Throws InputError("mass")
  // for a mass that is not block-diagonal or has a singular block, InputError("damping") for
  // dashpots on another lattice.
  LatticeSecondOrderSystem(LatticeStencils<D, C> mass, LatticeStencils<D, C> damping, LatticeStencils<D, C> stiffness,
                           ForceFunction force = {});
  // The same with the loads as nonzero entries (SparseLoads.hpp), which a rank can restrict to the
  // nodes it owns (lib/decomposition); an empty list is no load.
  LatticeSecondOrderSystem(LatticeStencils<D, C> mass, LatticeStencils<D, C> damping, LatticeStencils<D, C> stiffness,
                           std::vector<SparseLoad> loads);

  Index size() const override { return C * stiffness_.types().nodeCount(); }
  bool hasDamping() const override { return hasDamping_; }
  void acceleration(Real t, Eigen::Ref<const Vector> u, Eigen::Ref<const Vector> v, Eigen::Ref<Vector> a) override;

  void force(Real t, Vector& f) const override;
  void setForce(ForceFunction force) {
    force_ = std::move(force);
    loads_.reset();
  }
  bool hasForce() const { return static_cast<bool>(force_); }
  // The loads as nonzero entries when the system was built from them; null for a force given as a
  // function (or set by setForce).
  const std::vector<SparseLoad>* sparseLoads() const { return loads_.get(); }
  void applyStiffness(const Vector& x, Vector& y) const override { stiffness_.multiply(x, y); }
  Real kineticEnergy(const Vector& v) const override;
  Real strainEnergy(const Vector& u) const override;
  Real dampingPower(const Vector& v) const override;
  // Per lattice line along x node by node, then the lines in order (as the energies).
  Real dot(const Vector& a, const Vector& b) const override;
  // Serial vectors whose norms sum in lattice order (dot's), as a distributed system's do on any
  // number of ranks: an adaptive ARKODE run takes the same steps serially and on ranks.
  std::optional<VectorDistribution> distribution() const override;
  Vector lumpedMass() const override;
  // The diagonal of M per row type, C values each. Throws InputError("mass") when M is not diagonal.
  std::vector<Real> lumpedMassPerType() const;
  Vector stiffnessAbsoluteRowSums() const override { return stiffness_.absoluteRowSums(); }
  std::unique_ptr<CentredDampingSolve> centredDamping(Real dt, const std::vector<Index>& prescribedDofs) const override;

  const LatticeStencils<D, C>& mass() const { return mass_; }
  const LatticeStencils<D, C>& damping() const { return damping_; }
  const LatticeStencils<D, C>& stiffness() const { return stiffness_; }
  const LatticeRowTypes<D>& types() const { return stiffness_.types(); }
  // Bytes of the stencil tables and per-type inverses (nothing per particle).
  std::size_t bytes() const;

  // a_p = B_type (a_p - (K u)_p - (C v)_p) for every node, in place over a (which holds f): the
  // acceleration with B = M^-1, and the dashpot solve of eq. (32) with B = (M + dt/2 C)^-1.
  void fusedSolve(const std::vector<Real>& inverseBlocks, const Real* u, const Real* v, Real* a) const;
  // Per type, the inverse of M + s C (row-major C x C blocks).
  std::vector<Real> inverseBlocks(Real s) const;

 private:
  LatticeStencils<D, C> mass_, damping_, stiffness_;
  ForceFunction force_;
  std::shared_ptr<const std::vector<SparseLoad>> loads_;  // shared with force_
  bool hasDamping_ = false;
  std::vector<Real> inverseMass_;  // per type
};

extern template class LatticeSecondOrderSystem<1>;
extern template class LatticeSecondOrderSystem<2>;
extern template class LatticeSecondOrderSystem<3>;
extern template class LatticeSecondOrderSystem<2, 1>;
extern template class LatticeSecondOrderSystem<3, 1>;

}  // namespace mfwave
