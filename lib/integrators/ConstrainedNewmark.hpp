#pragma once
// Implicit Newmark (beta > 0) on a constrained system S d'' + A d = b (ConstrainedSecondOrderSystem;
// Luo-Liu-Huang eqs. (27)-(31) for collocation) in acceleration form, stepping the coefficients d:
//
//   d~ = d_n + dt v_n + dt^2 (1/2 - beta) a_n,   v~ = v_n + dt (1 - gamma) a_n      (28), (29)
//   (S + beta dt^2 A) a_{n+1} = b(t_{n+1}) - A d~                                    (27)
//   d_{n+1} = d~ + beta dt^2 a_{n+1},  v_{n+1} = v~ + gamma dt a_{n+1}               (30), (31)
//
// The constraint rows of S are zero, so there they read beta dt^2 A_B a_{n+1} = b_B - A_B d~, i.e.
// A_B d_{n+1} = b_B(t_{n+1}): the constraints (collocation's boundary conditions) hold exactly at
// every step. S* = S + beta dt^2 A is factorised once (sparse LU when square, sparse QR least
// squares when there are more equations than coefficients). It needs beta > 0 (with beta = 0,
// S* = S is singular): the explicit case is central difference on the system's SecondOrderSystem
// face. The initial d''_0 cannot come from S (singular) either: the system gives it.
//
// Observers see the same state as with the explicit path: U = P d and V = P d'.

#include "integrators/FixedStepSecondOrderIntegrator.hpp"
#include "solvers/FactorisedMatrix.hpp"
#include "systems/ConstrainedSecondOrderSystem.hpp"

namespace mfwave {

class ConstrainedNewmark : public FixedStepSecondOrderIntegrator {
 public:
  // beta in (0, 1/2], gamma in [0, 1]; otherwise InputError("integrator.newmark_beta" / "_gamma").
  explicit ConstrainedNewmark(Real beta = 0.25, Real gamma = 0.5);
  ~ConstrainedNewmark() override;

  std::string name() const override { return "newmark"; }
  // `system` must be a ConstrainedSecondOrderSystem (InputError("integrator") otherwise); u0, v0
  // are the observed values U0, V0. Throws mfwave::Error when S + beta dt^2 A is singular.
  void initialise(SecondOrderSystem& system, Real t0, const Vector& u0, const Vector& v0, Real dt) override;
  void step() override;

  Real beta() const { return beta_; }
  Real gamma() const { return gamma_; }
  // The coefficients d_n, d'_n, d''_n.
  const Vector& coefficients() const { return d_; }
  const Vector& coefficientRates() const { return dv_; }
  const Vector& coefficientAccelerations() const { return da_; }

 protected:
  // The coefficients d, d', d'' (u, v, a are their observed values).
  void saveHistory(StateArchive& archive) const override;
  void restoreHistory(const StateArchive& archive) override;

 private:
  Real beta_, gamma_;
  ConstrainedSecondOrderSystem* constrained_ = nullptr;
  FactorisedMatrix solver_;  // S + beta dt^2 A, factorised once (least squares when tall)
  Vector d_, dv_, da_, dPredict_, vPredict_, rhs_;
};

}  // namespace mfwave
