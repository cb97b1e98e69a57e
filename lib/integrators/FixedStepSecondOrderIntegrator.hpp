#pragma once
// Bookkeeping shared by the fixed-step integrators of u'' = a(t, u, u') (central difference,
// leapfrog, Newmark): the bound system, the step grid t_n = t0 + n dt, and the synchronous state
// (u_n, v_n, a_n). Derived classes implement step() and call advanceClock() once per step.

#include "integrators/Integrator.hpp"

namespace mfwave {

class FixedStepSecondOrderIntegrator : public SecondOrderIntegrator {
 public:
  Real time() const override { return time_; }
  long stepCount() const override { return steps_; }
  Real stepSize() const override { return dt_; }
  StateView state() const override { return {steps_, time_, u_, v_, dt_}; }
  // a_n at the current time.
  const Vector& acceleration() const { return a_; }

  // The clock (t0, dt, t_n, n), (u_n, v_n, a_n), the bound system's own state and the derived
  // scheme's history (saveHistory). restoreState checks that the step is the one this integrator
  // was initialised with: a checkpoint of another step is another run.
  void saveState(StateArchive& archive) const final;
  void restoreState(const StateArchive& archive) final;

 protected:
  // Checks the initial state (checkInitialState), stores it, resets the clock and sizes a_.
  void bind(SecondOrderSystem& system, Real t0, const Vector& u0, const Vector& v0, Real dt);
  // One step further on the grid. t0 + n dt, not a running sum, keeps time on the step grid for
  // advanceTo and the observers.
  void advanceClock() {
    ++steps_;
    time_ = t0_ + static_cast<Real>(steps_) * dt_;
  }
  // The closing half step shared by central difference and leapfrog, after u_{n+1} and the clock
  // have advanced: a_{n+1} = a(t_{n+1}, u_{n+1}, v*) and v_{n+1} = vHalf + dt/2 a_{n+1}. A
  // velocity-dependent system gets the predictor v* = vHalf + dt/2 a_n (an O(dt^2) estimate of
  // v_{n+1}: second order with one evaluation); otherwise v is not used and vPredict is untouched.
  void closeHalfStep(const Vector& vHalf, Vector& vPredict);
  // What a derived scheme carries between steps beyond (u_n, v_n, a_n) (none by default).
  virtual void saveHistory(StateArchive& archive) const { (void)archive; }
  virtual void restoreHistory(const StateArchive& archive) { (void)archive; }
  // Throws Error naming the integrator when step() comes before initialise().
  void requireInitialised() const;

  SecondOrderSystem* system_ = nullptr;
  Real t0_ = 0;
  Real dt_ = 0;
  Real time_ = 0;
  long steps_ = 0;
  Vector u_;  // u_n
  Vector v_;  // v_n (synchronous)
  Vector a_;  // a_n
};

}  // namespace mfwave
