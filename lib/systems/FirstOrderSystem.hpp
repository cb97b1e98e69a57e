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
};

}  // namespace mfwave
