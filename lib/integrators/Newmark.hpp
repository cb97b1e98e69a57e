#pragma once
// The Newmark family for linear systems M u'' + C u' + K u = f(t), in acceleration form
// (Luo-Liu-Huang eqs. 27-31):
//   predictors  u~ = u_n + dt v_n + dt^2 (1/2 - beta) a_n                      (28)
//               v~ = v_n + dt (1 - gamma) a_n                                  (29)
//   solve       (M + gamma dt C + beta dt^2 K) a_{n+1} = f(t_{n+1}) - C v~ - K u~   (27)
//   correctors  u_{n+1} = u~ + beta dt^2 a_{n+1},  v_{n+1} = v~ + gamma dt a_{n+1}   (30, 31)
// (Luo-Liu-Huang have no C; the damping term follows from the same derivation.)
// beta = 1/4, gamma = 1/2 (average acceleration, trapezoidal rule): unconditionally stable and
// energy-conserving for undamped systems. beta = 1/6, gamma = 1/2: linear acceleration, stable for
// w dt <= 2 sqrt(3). beta = 0, gamma = 1/2: central difference. gamma > 1/2 adds numerical damping
// and drops to first order; gamma < 1/2 is allowed but anti-damped (unstable).
//
// The effective matrix is constant (fixed dt, linear system): it is factorised once at
// initialise, with UMFPACK, or inverted entry-wise when it is diagonal (beta = 0 with lumped mass
// and damping). The initial acceleration solves M a_0 = f(t0) - C v0 - K u0 the same way.

#include "solvers/FactorisedMatrix.hpp"
#include "integrators/FixedStepSecondOrderIntegrator.hpp"

namespace mfwave {

class LinearSecondOrderSystem;

class Newmark : public FixedStepSecondOrderIntegrator {
 public:
  // beta in [0, 1/2], gamma in [0, 1]; otherwise InputError("newmark.beta" / "newmark.gamma").
  explicit Newmark(Real beta = 0.25, Real gamma = 0.5);

  std::string name() const override { return "newmark"; }
  // `system` must be a LinearSecondOrderSystem, else InputError("integrator", ...). Factorises M
  // and the effective matrix; throws mfwave::Error if either is singular.
  void initialise(SecondOrderSystem& system, Real t0, const Vector& u0, const Vector& v0, Real dt) override;
  void step() override;

  Real beta() const { return beta_; }
  Real gamma() const { return gamma_; }
  // True when the effective matrix was diagonal and no sparse factorisation was needed.
  bool effectiveMatrixIsDiagonal() const { return effective_.isDiagonal(); }

 private:
  Real beta_;
  Real gamma_;
  LinearSecondOrderSystem* linear_ = nullptr;  // system_, seen as the linear system it must be
  Vector uPredict_, vPredict_, rhs_, aNext_;
  FactorisedMatrix effective_;
};

}  // namespace mfwave
