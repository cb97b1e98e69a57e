#pragma once
// What every time integrator offers the time loop and the observers: advance one step, and show
// the current state. Integrators see only semi-discrete systems (lib/systems), never particles.

#include "core/StateArchive.hpp"
#include "core/Types.hpp"
#include "systems/SecondOrderSystem.hpp"

#include <string>

namespace mfwave {

// A read-only view of the state at one instant, handed to observers.
// For a second-order system: displacement u and velocity v (both of the system's size).
struct StateView {
  long step;
  Real time;
  const Vector& displacement;
  const Vector& velocity;
  // The step just taken (before the first step: the step about to be taken), so that observers
  // need not derive it from time differences.
  Real dt = 0;
};

class Integrator {
 public:
  virtual ~Integrator() = default;
  virtual std::string name() const = 0;
  // Advance by one step (for adaptive integrators: one internal step, of whatever size it chose).
  virtual void step() = 0;
  // Advance to exactly time t (t >= time()); fixed-step integrators take whole steps and require
  // t to lie on the step grid within round-off.
  virtual void advanceTo(Real t);
  virtual Real time() const = 0;
  virtual long stepCount() const = 0;
  // Size of the last step taken (or of the next, before the first).
  virtual Real stepSize() const = 0;
  virtual StateView state() const = 0;

  // Checkpoints (issue 20): everything a later restoreState needs to go on bitwise as if the run
  // had never stopped (the state, the clock, the scheme's history, the bound system's own state).
  // restoreState is called on an integrator initialised as for the original run (same system, same
  // step), and replaces only what changes while stepping. The defaults throw Error: an integrator
  // that cannot be checkpointed says so before the first step (TimeLoop tries a save first).
  virtual void saveState(StateArchive& archive) const;
  virtual void restoreState(const StateArchive& archive);
};

// An integrator of u'' = a(t, u, u').
class SecondOrderIntegrator : public Integrator {
 public:
  // Binds the system and sets the state (u0, v0) at time t0 with step dt (> 0).
  // The system must outlive the integrator's use.
  virtual void initialise(SecondOrderSystem& system, Real t0, const Vector& u0, const Vector& v0, Real dt) = 0;
};

// What every SecondOrderIntegrator::initialise checks first: u0 and v0 have the system's size and
// are finite, t0 is finite, dt is positive and finite. Throws InputError ("initial_state",
// "time_step").
void checkInitialState(const SecondOrderSystem& system, Real t0, const Vector& u0, const Vector& v0, Real dt);

}  // namespace mfwave
