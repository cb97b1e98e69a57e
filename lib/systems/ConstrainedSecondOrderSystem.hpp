#pragma once
// A second-order system written in generalised coefficients d whose mass is singular where
// constraints stand (Luo-Liu-Huang eq. (27)):
//
//   S d'' + A d = b(t),   S zero on the constraint rows (boundary conditions of collocation),
//
// and whose state seen by observers is U = P d at the unconstrained points. Such a system has two
// faces. As a SecondOrderSystem it is the explicit one, a(t, U) with the constraints imposed at
// every instant (any explicit integrator steps it in U). As a ConstrainedSecondOrderSystem it hands
// an implicit integrator what it needs to step in d, where S + beta dt^2 A is regular and the
// constraint rows hold exactly at every step (ConstrainedNewmark). MFEM's TimeDependentOperator
// with its ImplicitSolve is the model: the system says what it is, the integrator how to step it.

#include "core/Types.hpp"
#include "systems/SecondOrderSystem.hpp"

namespace mfwave {

class ConstrainedSecondOrderSystem : public SecondOrderSystem {
 public:
  // S and A (rows: every equation, columns: the coefficients) and b(t).
  virtual const SparseMatrix& coefficientMass() const = 0;
  virtual const SparseMatrix& coefficientStiffness() const = 0;
  virtual Vector coefficientLoad(Real t) const = 0;
  // The coefficients of a state: d, d' and d'' from the values U, V at time t (the constraint
  // data of t, its rate and its second rate joined to them).
  virtual Vector coefficients(const Vector& U, Real t) const = 0;
  virtual Vector coefficientRates(const Vector& V, Real t) const = 0;
  virtual Vector coefficientAccelerations(const Vector& U, Real t) = 0;
  // U = P d: the values observers see.
  virtual Vector observedValues(const Vector& d) const = 0;
};

}  // namespace mfwave
