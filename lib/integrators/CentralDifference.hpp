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

#include "integrators/Integrator.hpp"

namespace mfwave {

class CentralDifference : public SecondOrderIntegrator {
 public:
  std::string name() const override { return "central_difference"; }
  // Evaluates a_0 = a(t0, u0, v0) once.
  void initialise(SecondOrderSystem& system, Real t0, const Vector& u0, const Vector& v0, Real dt) override;
  void step() override;
  Real time() const override { return time_; }
  long stepCount() const override { return steps_; }
  Real stepSize() const override { return dt_; }
  StateView state() const override { return {steps_, time_, u_, v_}; }

  // The scheme's own velocity v_{n-1/2}, and the acceleration a_n at the current time.
  const Vector& staggeredVelocity() const { return vHalf_; }
  const Vector& acceleration() const { return a_; }

 private:
  SecondOrderSystem* system_ = nullptr;
  Real t0_ = 0;
  Real dt_ = 0;
  Real time_ = 0;
  long steps_ = 0;
  Vector u_;          // u_n
  Vector vHalf_;      // v_{n-1/2}
  Vector v_;          // v_n (synchronous, reported)
  Vector a_;          // a_n
  Vector vPredict_;   // v_n* (velocity-dependent systems only)
};

}  // namespace mfwave
