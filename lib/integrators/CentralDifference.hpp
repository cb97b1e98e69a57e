#pragma once
// The explicit central-difference scheme u_{n+1} = 2 u_n - u_{n-1} + dt^2 a_n (Ding-Long-Wu
// eq. 23), second order, conditionally stable (w dt <= 2 for an undamped mode of frequency w).
//
// It is carried in the algebraically equivalent staggered form (u_n, v_{n-1/2}):
//   v_{n+1/2} = v_{n-1/2} + dt a_n,   u_{n+1} = u_n + dt v_{n+1/2},
// because differencing u directly loses digits (2 u_n - u_{n-1} cancels when dt is small), while the
// staggered velocity keeps the increment at full precision. Same trajectory, better round-off.
//
// Start: v_{-1/2} = v_0 - dt/2 a_0, so u_1 = u_0 + dt v_0 + dt^2/2 a_0 (the Taylor start).
// Velocity-dependent accelerations (damping, dashpots) are evaluated with the predictor
// v_n* = v_{n-1/2} + dt/2 a_{n-1}, which keeps the scheme second order and explicit.
// The reported (synchronous) velocity is v_n = v_{n-1/2} + dt/2 a_n.
// Exactly one acceleration evaluation per step; a_n is kept from the previous step.

#include "integrators/FixedStepSecondOrderIntegrator.hpp"

namespace mfwave {

class CentralDifference : public FixedStepSecondOrderIntegrator {
 public:
  std::string name() const override { return "central_difference"; }
  // Evaluates a_0 = a(t0, u0, v0) once.
  void initialise(SecondOrderSystem& system, Real t0, const Vector& u0, const Vector& v0, Real dt) override;
  void step() override;

  // The scheme's own velocity v_{n-1/2}.
  const Vector& staggeredVelocity() const { return vHalf_; }

 private:
  Vector vHalf_;      // v_{n-1/2}
  Vector vPredict_;   // v_n* (velocity-dependent systems only)
};

}  // namespace mfwave
