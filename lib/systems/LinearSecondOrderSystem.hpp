#pragma once
// The linear case M u'' + C u' + K u = f(t), with sparse M, C, K assembled once (linear
// elastodynamics on fixed particles, collocation). Implicit integrators (Newmark) use the matrices;
// explicit ones use acceleration(): with a diagonal (lumped) M by reciprocals, with a consistent M
// by a sparse LU of M factorised on the first call (solvers/FactorisedMatrix), which is what lets
// explicit integrators run a consistent-mass operator (the stability atlas confirms the limits of
// RK and RB collocation that way).

#include "systems/LinearOperatorSystem.hpp"

#include <functional>
#include <memory>

namespace mfwave {

class FactorisedMatrix;

class LinearSecondOrderSystem : public LinearOperatorSystem {
 public:
  using ForceFunction = std::function<void(Real t, Vector& f)>;

  // M, C, K must be square and of the same size; C may be empty (0 x 0) for no damping.
  // `force` fills f(t) (size n); an empty function means f = 0.
  LinearSecondOrderSystem(SparseMatrix mass, SparseMatrix damping, SparseMatrix stiffness,
                          ForceFunction force = {});

  Index size() const override { return stiffness_.rows(); }

  // a = M^{-1} (f(t) - C v - K u). Throws InputError("mass") for a diagonal M with an entry <= 0,
  // mfwave::Error for a singular consistent M.
  void acceleration(Real t, Eigen::Ref<const Vector> u, Eigen::Ref<const Vector> v,
                    Eigen::Ref<Vector> a) override;

  // M^{-1} b, with the factorisation acceleration() solves with (made on the first call of either):
  // for instance the collocation coefficients of nodal values. Same errors as acceleration().
  Vector solveMass(const Vector& b);

  const SparseMatrix& mass() const { return mass_; }
  const SparseMatrix& damping() const { return damping_; }  // 0 x 0 when undamped
  const SparseMatrix& stiffness() const { return stiffness_; }
  bool hasDamping() const override { return damping_.nonZeros() > 0; }
  void force(Real t, Vector& f) const override;
  // Replaces f(t): loads are attached after a method has assembled M, C and K.
  void setForce(ForceFunction force) { force_ = std::move(force); }
  // Replaces C (empty for none): boundary dashpots are assembled after the method's M and K.
  // Set it before an integrator is initialised with the system (implicit schemes factorise it).
  // Throws InputError("damping") for a wrong size.
  void setDamping(SparseMatrix damping);

  // Total mechanical energy 1/2 v^T M v + 1/2 u^T K u (meaningful for symmetric K).
  Real kineticEnergy(const Vector& v) const override;
  Real strainEnergy(const Vector& u) const override;

  // LinearOperatorSystem
  void applyStiffness(const Vector& x, Vector& y) const override { y.noalias() = stiffness_ * x; }
  Real dampingPower(const Vector& v) const override;
  Vector lumpedMass() const override;
  Vector stiffnessAbsoluteRowSums() const override;
  // ImplicitDampingSolver: M + dt/2 C factorised (FactorisedMatrix).
  std::unique_ptr<CentredDampingSolve> centredDamping(Real dt, const std::vector<Index>& prescribedDofs) const override;

 private:
  // Checks a lumped M, or factorises a consistent one on first use.
  void prepareMassSolve();
  // Takes the storage of `damping` (left empty) after checking its size.
  void adoptDamping(SparseMatrix& damping);
  // out -= K u, OpenMP-parallel over rows of a row-major copy of K (bitwise thread-independent).
  void subtractStiffnessProduct(Eigen::Ref<const Vector> u, Vector& out);

  SparseMatrix mass_;
  SparseMatrix damping_;
  SparseMatrix stiffness_;
  Eigen::SparseMatrix<Real, Eigen::RowMajor, int> stiffnessRows_;  // for explicit steps; built on first use
  ForceFunction force_;
  Vector inverseMassDiagonal_;  // empty when M is not diagonal
  bool diagonalMass_ = false;
  // M's LU when it is not diagonal, made on the first acceleration(); shared by copies of the system.
  std::shared_ptr<const FactorisedMatrix> massSolver_;
  Vector massSolution_;
  Vector work_;
};

}  // namespace mfwave
