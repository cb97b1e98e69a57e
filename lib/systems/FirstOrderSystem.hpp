#pragma once
// A semi-discrete system of first order in time, y' = F(t, y): what ARKODE integrates, and the
// form of updated-Lagrangian SPH (positions, velocities, densities, stresses, energies).

#include "core/Types.hpp"

namespace mfwave {

class FirstOrderSystem {
 public:
  virtual ~FirstOrderSystem() = default;
  virtual Index size() const = 0;
  // ydot = F(t, y); ydot has size().
  virtual void rhs(Real t, const Vector& y, Vector& ydot) = 0;

  // The same on views of foreign storage (ARKODE's N_Vector data), so an adapter can evaluate F
  // without copying y in and ydot out. ydot already has size(). A distinct name, not an overload,
  // so systems that override only rhs() do not hide it (-Woverloaded-virtual). The default copies;
  // systems on a hot path override it.
  virtual void rhsView(Real t, Eigen::Ref<const Vector> y, Eigen::Ref<Vector> ydot) {
    const Vector yCopy = y;
    Vector ydotCopy(size());
    rhs(t, yCopy, ydotCopy);
    ydot = ydotCopy;
  }
};

}  // namespace mfwave
