#pragma once
// A linear second-order system M u'' + C u' + K u = f(t) seen through its operators, not its
// storage: what the central-difference dashpot solve, the stable-step estimate and the energy
// ledger need from it. Two implementations: LinearSecondOrderSystem (assembled sparse matrices,
// any particle set) and LatticeSecondOrderSystem (per-row-type stencils on a box lattice,
// lib/lattice). An integrator or observer written against this class runs on either.

#include "systems/SecondOrderSystem.hpp"

#include <functional>
#include <memory>
#include <vector>

namespace mfwave {

// One step's dashpot solve of central difference (Ding-Long-Wu eq. (32)):
// (M + dt/2 C) a = f(t) - K u - C vHalf, with a[prescribedDofs] = prescribedAcceleration.
class CentredDampingSolve {
 public:
  virtual ~CentredDampingSolve() = default;
  // `prescribedAcceleration` has one entry per prescribed dof (ignored when there are none).
  virtual void acceleration(Real t, const Vector& u, const Vector& vHalf, const Vector& prescribedAcceleration,
                            Vector& a) = 0;
};

class LinearOperatorSystem : public SecondOrderSystem {
 public:
  bool dependsOnVelocity() const override { return hasDamping(); }
  virtual bool hasDamping() const = 0;

  // f(t), resized to size() and overwritten.
  virtual void force(Real t, Vector& f) const = 0;
  // y = K x (y resized).
  virtual void applyStiffness(const Vector& x, Vector& y) const = 0;
  // 1/2 v^T M v, 1/2 u^T K u and the dashpot power v^T C v.
  virtual Real kineticEnergy(const Vector& v) const = 0;
  virtual Real strainEnergy(const Vector& u) const = 0;
  virtual Real dampingPower(const Vector& v) const = 0;
  // a . b over all the system's unknowns (the load work of the energy ledger). A system may fix the
  // order of the sum, so that a distributed system (lib/decomposition) gives its serial bits.
  virtual Real dot(const Vector& a, const Vector& b) const { return a.dot(b); }
  // The largest of `value` over the ranks of a distributed system (collective), `value` otherwise.
  virtual Real maximum(Real value) const { return value; }
  // Each of this system's values set from its global unknown's number (the place it has in the
  // serial system): value(i) for unknown i here; a distributed system maps its own.
  virtual void fillByGlobalIndex(Vector& x, const std::function<Real(Index)>& value) const {
    x.resize(size());
    for (Index i = 0; i < size(); ++i) x[i] = value(i);
  }
  // The diagonal of a lumped M; throws InputError("mass") when M is not diagonal.
  virtual Vector lumpedMass() const = 0;
  // sum_j |K_ij| for every row i (Gershgorin).
  virtual Vector stiffnessAbsoluteRowSums() const = 0;
  // The solve of eq. (32) for step dt with the rows of prescribedDofs replaced by their known
  // accelerations. The system must outlive it.
  virtual std::unique_ptr<CentredDampingSolve> centredDamping(Real dt, const std::vector<Index>& prescribedDofs) const = 0;
};

}  // namespace mfwave
