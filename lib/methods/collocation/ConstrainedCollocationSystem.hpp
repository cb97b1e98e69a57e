#pragma once
// The explicit form of collocation (Newmark beta = 0, central difference) with the boundary rows
// as constraints; its ConstrainedSecondOrderSystem face (S, A, b in the coefficients) is what the
// implicit ConstrainedNewmark steps. S d'' + A d = b has zero mass on its boundary rows, so it cannot be solved for
// d''. Instead the unknowns are the nodal VALUES at the interior collocation points,
//
//   U = Psi_I d                    (Psi_I = S_I / rho: psi_J at the interior points, per component)
//
// and the boundary rows B d = b_B(t) (B = A_B: traction rows B^h psi, displacement rows psi) are
// imposed at every instant. With the constraint matrix
//
//   C = [Psi_I; B]                 (rows: interior rows in order, then boundary rows in order)
//
// factorised once, d = C^{-1} [U; b_B(t)] and the interior rows give
//
//   U'' = a(t, U) = (1/rho) (b_I(t) - A_I d).
//
// For zero loads and zero boundary data a = -K U with K = (1/rho) A_I C^{-1} [I; 0]: the matrix
// G-bar of the von Neumann analysis (Luo-Liu-Huang eq. (37), up to the sign and c^2).
//
// Nc = Ns (C square): sparse LU (UMFPACK). Nc > Ns (C tall): d is the
// least-squares solution of C d = [U; b_B] (SuiteSparseQR, i.e. C^+ [U; b_B], the pseudo-inverse
// Luo-Liu-Huang name for M^{-1} when Nc > Ns); then U = Psi_I d holds only in the least-squares
// sense, and coefficients(U) followed by interiorValues(d) does not return U exactly.

#include <memory>
#include <vector>

#include "methods/collocation/CollocationSystem.hpp"
#include "solvers/FactorisedMatrix.hpp"
#include "systems/ConstrainedSecondOrderSystem.hpp"

namespace mfwave {

class ConstrainedCollocationSystem : public ConstrainedSecondOrderSystem {
 public:
  // Throws InputError("collocation.points") when there are fewer collocation rows than
  // coefficients (Nc < Ns) or no interior row, and mfwave::Error when C is singular (or, tall,
  // rank-deficient).
  explicit ConstrainedCollocationSystem(CollocationSystem system);
  ~ConstrainedCollocationSystem() override;
  ConstrainedCollocationSystem(const ConstrainedCollocationSystem&) = delete;
  ConstrainedCollocationSystem& operator=(const ConstrainedCollocationSystem&) = delete;

  // Interior rows x components.
  Index size() const override { return static_cast<Index>(interiorRows_.size()); }
  bool dependsOnVelocity() const override { return false; }
  // a = (1/rho) (b_I(t) - A_I C^{-1} [U; b_B(t)]).
  void acceleration(Real t, Eigen::Ref<const Vector> u, Eigen::Ref<const Vector> v, Eigen::Ref<Vector> a) override;

  // --- ConstrainedSecondOrderSystem: S, A and b of the collocation system, U = Psi_I d.
  const SparseMatrix& coefficientMass() const override { return system_.S; }
  const SparseMatrix& coefficientStiffness() const override { return system_.A; }
  Vector coefficientLoad(Real t) const override { return system_.rhs(t); }
  Vector observedValues(const Vector& d) const override { return interiorValues(d); }

  // d = C^{-1} [U; b_B(t)] (least squares when Nc > Ns).
  Vector coefficients(const Vector& U, Real t) const override;
  // d' = C^{-1} [V; b_B'(t)], b_B' by a central difference of the load with step
  // 1e-4 max(1, |t|) (exact for boundary data linear in t; zero when there is no load).
  Vector coefficientRates(const Vector& V, Real t) const override;
  // d'' = C^{-1} [a(t, U); b_B''(t)] (second central difference of the load, same step).
  Vector coefficientAccelerations(const Vector& U, Real t) override;
  // C^{-1} [top; bottom] for any right-hand side (top: size(), bottom: boundaryRows().size()).
  Vector solveConstraint(const Vector& top, const Vector& bottom) const;
  // Linear functionals of the coefficients written on the constraint's right-hand side: for each
  // column r of `functionals` (cols() entries: r . d is, e.g., u^h_i(x) = sum_J psi_J(x) d_Ji), the
  // column g = C^{-T} r, so that r . C^{-1} [top; bottom] = g . [top; bottom]. Sampling u^h at a few
  // points every step then costs a dot product instead of a solve (r . d' = g . [V; b_B'(t)]).
  // Factorises C^T once per call; square C only (throws mfwave::Error when least squares).
  Eigen::MatrixXd constraintAdjoint(const Eigen::MatrixXd& functionals) const;
  // U = Psi_I d.
  Vector interiorValues(const Vector& d) const { return psiInterior_ * d; }
  // Boundary data b_B(t) (size boundaryRows().size()).
  Vector boundaryData(Real t) const;
  // Its rate b_B'(t) (order 1) or b_B''(t) (order 2) by central differences of the load with step
  // 1e-4 max(1, |t|): what coefficientRates and coefficientAccelerations join to V and a. Zero when
  // there is no load.
  Vector boundaryDataRate(Real t, int order) const;

  // K (size() x size(), dense) with a = -K U for zero loads and zero boundary data. Costs a
  // solve with size() right-hand sides: for small systems (stability analysis).
  Eigen::MatrixXd denseStiffness() const;

  const CollocationSystem& system() const { return system_; }
  // Row numbers (of S, A, b) of the interior rows and of the boundary rows, in C's order.
  const std::vector<Index>& interiorRows() const { return interiorRows_; }
  const std::vector<Index>& boundaryRows() const { return boundaryRows_; }
  const SparseMatrix& constraintMatrix() const { return constraint_; }  // C
  const SparseMatrix& interiorOperator() const { return aInterior_; }   // A_I
  const SparseMatrix& interiorValuesMatrix() const { return psiInterior_; }  // Psi_I
  bool isLeastSquares() const { return constraint_.rows() > constraint_.cols(); }

 private:
  CollocationSystem system_;
  std::vector<Index> interiorRows_, boundaryRows_;
  SparseMatrix psiInterior_, aInterior_, constraint_;
  FactorisedMatrix solver_;  // C = [Psi_I; B]: sparse LU, or least squares when Nc > Ns
  Vector b_, d_, rhs_;
};

}  // namespace mfwave
