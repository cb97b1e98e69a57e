#pragma once
// A first-order system whose state splits as y = [q; p]: a configuration q (positions, densities,
// deviatoric stresses) whose rate depends mainly on p, and a momentum part p (velocities, specific
// internal energies, energy-ledger integrals) whose rate depends mainly on q. Updated-Lagrangian SPH
// has this form; it is what lets the leapfrog (kick-drift-kick) integrate it with one evaluation of
// each part per step, the staggered scheme SPH codes use for solids.

#include "systems/FirstOrderSystem.hpp"

namespace mfwave {

class SplitFirstOrderSystem : public FirstOrderSystem {
 public:
  // q is y[0, configurationSize()), p is y[configurationSize(), size()).
  virtual Index configurationSize() const = 0;
  // dq/dt at (t, y); qdot has configurationSize() entries.
  virtual void configurationRate(Real t, Eigen::Ref<const Vector> y, Eigen::Ref<Vector> qdot) = 0;
  // dp/dt at (t, y); pdot has size() - configurationSize() entries.
  virtual void momentumRate(Real t, Eigen::Ref<const Vector> y, Eigen::Ref<Vector> pdot) = 0;

  // Both parts. Systems override it when one pass over the data gives both more cheaply.
  void rhs(Real t, Eigen::Ref<const Vector> y, Eigen::Ref<Vector> ydot) override {
    const Index nq = configurationSize();
    configurationRate(t, y, ydot.head(nq));
    momentumRate(t, y, ydot.tail(size() - nq));
  }
};

}  // namespace mfwave
