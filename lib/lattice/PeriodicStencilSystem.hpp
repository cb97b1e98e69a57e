#pragma once
// u'' = A u on an N^D periodic lattice with one stencil on every node (the interior row of a
// translation-invariant method repeated, as in the planewave study and the spectra), applied by
// lattice arithmetic: no matrix, no per-node storage. The matrix-free counterpart of
// periodicLatticeSystem's sparse matrices (lib/numerics/PeriodicLattice) for lumped methods
// (M = I, no dampers, no loads): K = -A.
//
// Each lattice line along x runs its middle, where no x offset wraps, through stencilRun (the
// vectorised kernel of the box-lattice stencils) with the neighbouring lines' offsets wrapped for
// that line; the reach nodes at each end sum their rows directly with x wrapped. A node always takes
// the same path, so results are bitwise the same on any thread count.
//
// D is the lattice dimension, C the unknowns per node (1 for a scalar wave, D for elasticity).
// Unknowns are node * C + component, nodes x fastest.

#include "core/Types.hpp"
#include "systems/LinearOperatorSystem.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace mfwave {

template <int D, int C>
class PeriodicStencilSystem : public LinearOperatorSystem {
 public:
  // The stencil of A: offsets in lattice steps and C x C row-major blocks, one per offset. Throws
  // InputError("cells") for an odd N or a stencil that reaches N / 2 nodes or further along an axis
  // (its periodic images would overlap), InputError("stencil") for an empty stencil, blocks of the
  // wrong size or an offset given twice.
  PeriodicStencilSystem(int cells, const std::vector<std::array<int, D>>& steps, const std::vector<Real>& blocks);

  int cells() const { return cells_; }
  Index nodes() const { return nodes_; }
  Index size() const override { return C * nodes_; }
  bool hasDamping() const override { return false; }
  bool dependsOnVelocity() const override { return false; }

  // a = A u (M = I, no loads).
  void acceleration(Real t, Eigen::Ref<const Vector> u, Eigen::Ref<const Vector> v, Eigen::Ref<Vector> a) override;
  // y = A x.
  void multiply(const Real* x, Real* y) const;

  void force(Real t, Vector& f) const override;
  void applyStiffness(const Vector& x, Vector& y) const override;
  Real kineticEnergy(const Vector& v) const override { return 0.5 * v.squaredNorm(); }
  Real strainEnergy(const Vector& u) const override;
  Real dampingPower(const Vector&) const override { return 0; }
  Vector lumpedMass() const override { return Vector::Ones(size()); }
  Vector stiffnessAbsoluteRowSums() const override;
  std::unique_ptr<CentredDampingSolve> centredDamping(Real dt, const std::vector<Index>& prescribedDofs) const override;

  // Bytes of the stencil (nothing per node).
  std::size_t bytes() const;

 private:
  int cells_ = 0, reach_ = 0;
  Index nodes_ = 0, lines_ = 0;
  std::vector<std::array<int, D>> steps_;  // sorted like node indices (z, y, x)
  std::vector<Real> blocks_;               // C * C per entry, row-major
  std::vector<Index> dx_;                  // per entry: the x step
  std::uint64_t tableNumber_ = 0;          // for stencilRun's per-thread terms
};

extern template class PeriodicStencilSystem<1, 1>;
extern template class PeriodicStencilSystem<2, 1>;
extern template class PeriodicStencilSystem<2, 2>;
extern template class PeriodicStencilSystem<3, 1>;
extern template class PeriodicStencilSystem<3, 3>;

}  // namespace mfwave
