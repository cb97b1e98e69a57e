#pragma once
// A semi-discrete system of first order in time, y' = F(t, y): what ARKODE integrates, and the
// form of updated-Lagrangian SPH (positions, velocities, densities, stresses, energies).

#include "core/Types.hpp"

namespace mfwave {

class FirstOrderSystem {
 public:
  virtual ~FirstOrderSystem() = default;
  virtual Index size() const = 0;
  // ydot = F(t, y); y and ydot have size(). Eigen::Ref takes whole vectors or views of foreign
  // storage (ARKODE's N_Vector data), so adapters evaluate F without copies.
  virtual void rhs(Real t, Eigen::Ref<const Vector> y, Eigen::Ref<Vector> ydot) = 0;
};

}  // namespace mfwave
