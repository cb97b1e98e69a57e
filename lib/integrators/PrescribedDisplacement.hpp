#pragma once
// Displacements imposed on chosen dofs of an explicit scheme, Ding-Long-Wu eq. (30):
// u^a(t + dt) = g(x^a, t + dt) replaces the update of those particles. CentralDifference owns one
// when setPrescribedDisplacement was called; this class keeps the dofs, g and the last three values
// g_n, g_{n+1}, g_{n+2}, so that g is evaluated once per step.
//
// What the scheme sees at a prescribed dof, after step n+1 (time t_{n+1}):
//   v_{n+1/2} = (g_{n+1} - u_n) / dt        (imposed before the drift)
//   u_{n+1}   = g_{n+1}                     (exactly, after the drift)
//   v_{n+1}   = (g_{n+2} - g_n) / (2 dt)    (the mean of v_{n+1/2} and v_{n+3/2}, second order)
//   a_{n+1}   = (g_{n+2} - 2 g_{n+1} + g_n) / dt^2
// i.e. the central-difference velocity and acceleration of the prescribed motion itself.

#include "core/StateArchive.hpp"
#include "core/Types.hpp"

#include <functional>
#include <vector>

namespace mfwave {

class PrescribedDisplacement {
 public:
  // g(t, values) fills values (sized dofs.size() on entry) with g(t) at the dofs.
  using Function = std::function<void(Real t, Vector& values)>;

  // Throws InputError("prescribed_displacement") for an empty g with dofs, negative or repeated dofs.
  PrescribedDisplacement(std::vector<Index> dofs, Function g);

  // At initialise: checks the dofs against the system size (InputError "prescribed_displacement")
  // and u0[dofs] against g(t0): they must agree to 1e-12 relative to the largest |u0| or |g(t0)|
  // (InputError "initial_displacement" otherwise: a mismatch would be a jump, i.e. an impulse), then
  // sets u0[dofs] = g(t0) exactly. Evaluates g(t0) and g(t0 + dt).
  void bind(Index systemSize, Real t0, Real dt, Vector& u0);

  const std::vector<Index>& dofs() const { return dofs_; }

  // Step n -> n+1, before the drift: v_{n+1/2}[dofs] = (g_{n+1} - u_n[dofs]) / dt.
  void imposeHalfStepVelocity(const Vector& u, Real dt, Vector& vHalf) const;
  // After the drift: u_{n+1}[dofs] = g_{n+1}.
  void imposeDisplacement(Vector& u) const;
  // At t_{n+1}, given tAfter = t_{n+2}: evaluates g_{n+2}, forms the velocity and acceleration
  // above and moves the window on by one step.
  void advance(Real tAfter, Real dt);
  // a_{n+1} and v_{n+1} at the dofs (valid after advance).
  const Vector& acceleration() const { return acceleration_; }
  const Vector& velocity() const { return velocity_; }
  // The window g_n, g_{n+1} and the reported v, a (for checkpoints).
  void saveState(StateArchive& archive) const;
  void restoreState(const StateArchive& archive);
  // full[dofs] = values.
  void scatter(const Vector& values, Vector& full) const;

 private:
  void evaluate(Real t, Vector& values) const;  // g(t), checked for size and finiteness

  std::vector<Index> dofs_;
  Function g_;
  Vector current_;  // g_n      (g at the integrator's current time)
  Vector next_;     // g_{n+1}
  Vector after_;    // g_{n+2} (work)
  Vector acceleration_;
  Vector velocity_;
};

}  // namespace mfwave
