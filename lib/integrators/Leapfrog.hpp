#pragma once
// Leapfrog in kick-drift-kick (velocity Verlet) form on the synchronous state (u_n, v_n):
//   v_{n+1/2} = v_n + dt/2 a_n                 (kick)
//   u_{n+1}   = u_n + dt v_{n+1/2}             (drift)
//   a_{n+1}   = a(t_{n+1}, u_{n+1}, v*)        v* = v_{n+1/2} + dt/2 a_n, only if a depends on v
//   v_{n+1}   = v_{n+1/2} + dt/2 a_{n+1}       (kick)
// Symplectic and second order; for velocity-independent systems its u trajectory is the
// central-difference one (Ding-Long-Wu eq. 23) up to round-off, since v_n + dt/2 a_n = v_{n-1/2} +
// dt a_n. It differs only in which velocity is stored. One acceleration evaluation per step
// (a_n is kept from the previous step).

#include "integrators/FixedStepSecondOrderIntegrator.hpp"

namespace mfwave {

class Leapfrog : public FixedStepSecondOrderIntegrator {
 public:
  std::string name() const override { return "leapfrog"; }
  // Evaluates a_0 = a(t0, u0, v0) once.
  void initialise(SecondOrderSystem& system, Real t0, const Vector& u0, const Vector& v0, Real dt) override;
  void step() override;

 private:
  Vector vHalf_;      // v_{n+1/2} (work)
  Vector vPredict_;   // v* (velocity-dependent systems only)
};

}  // namespace mfwave
