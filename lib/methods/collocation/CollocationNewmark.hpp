#pragma once
// Implicit Newmark (beta > 0) for collocation, on the full system S d'' + A d = b (Luo-Liu-Huang
// eqs. (27)-(31)) in acceleration form, with d the RK coefficients:
//
//   d~ = d_n + dt v_n + dt^2 (1/2 - beta) a_n,   v~ = v_n + dt (1 - gamma) a_n      (28), (29)
//   (S + beta dt^2 A) a_{n+1} = b(t_{n+1}) - A d~                                    (27)
//   d_{n+1} = d~ + beta dt^2 a_{n+1},  v_{n+1} = v~ + gamma dt a_{n+1}               (30), (31)
//
// The boundary rows of S are zero, so there they read beta dt^2 A_B a_{n+1} = b_B - A_B d~, i.e.
// A_B d_{n+1} = b_B(t_{n+1}): the boundary conditions hold exactly at every step. S* = S + beta
// dt^2 A is factorised once (sparse LU when Nc = Ns, sparse QR least squares when Nc > Ns).
// It needs beta > 0 (with beta = 0, S* = S is singular): the explicit case is central difference
// on ConstrainedCollocationSystem. The initial d''_0 cannot come from S (singular) either: it is
// C^{-1} [a(t0, U0); b_B''(t0)] from the constrained system.
//
// It is a SecondOrderIntegrator of the ConstrainedCollocationSystem, so time loops and observers
// see the same state as with the explicit path: U = Psi_I d and V = Psi_I d' at the interior points.

#include <memory>

#include "integrators/FactorisedMatrix.hpp"
#include "integrators/FixedStepSecondOrderIntegrator.hpp"
#include "methods/collocation/ConstrainedCollocationSystem.hpp"

namespace mfwave {

class CollocationNewmark : public FixedStepSecondOrderIntegrator {
 public:
  // beta in (0, 1/2], gamma in [0, 1]; otherwise InputError("integrator.newmark_beta" / "_gamma").
  explicit CollocationNewmark(Real beta = 0.25, Real gamma = 0.5);
  ~CollocationNewmark() override;

  std::string name() const override { return "newmark"; }
  // `system` must be a ConstrainedCollocationSystem (InputError("integrator") otherwise); u0, v0
  // are the interior values U0, V0. Throws mfwave::Error when S + beta dt^2 A is singular.
  void initialise(SecondOrderSystem& system, Real t0, const Vector& u0, const Vector& v0, Real dt) override;
  void step() override;

  Real beta() const { return beta_; }
  Real gamma() const { return gamma_; }
  // The coefficients d_n, d'_n, d''_n.
  const Vector& coefficients() const { return d_; }
  const Vector& coefficientRates() const { return dv_; }
  const Vector& coefficientAccelerations() const { return da_; }

 private:
  Real beta_, gamma_;
  ConstrainedCollocationSystem* constrained_ = nullptr;
  FactorisedMatrix solver_;  // S + beta dt^2 A, factorised once (least squares when Nc > Ns)
  Vector d_, dv_, da_, dPredict_, vPredict_, rhs_;
};

}  // namespace mfwave
