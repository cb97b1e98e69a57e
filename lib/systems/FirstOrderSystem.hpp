#pragma once
// A semi-discrete system of first order in time, y' = F(t, y): what ARKODE integrates, and the
// form of updated-Lagrangian SPH (positions, velocities, densities, stresses, energies).

#include "core/StateArchive.hpp"
#include "core/Types.hpp"
#include "systems/VectorDistribution.hpp"

#include <optional>

namespace mfwave {

class FirstOrderSystem {
 public:
  virtual ~FirstOrderSystem() = default;
  virtual Index size() const = 0;
  // ydot = F(t, y); y and ydot have size(). Eigen::Ref takes whole vectors or views of foreign
  // storage (ARKODE's N_Vector data), so adapters evaluate F without copies.
  virtual void rhs(Real t, Eigen::Ref<const Vector> y, Eigen::Ref<Vector> ydot) = 0;

  // A system that holds one rank's share of y says so here (VectorDistribution.hpp): ARKODE then
  // works on SUNDIALS' MPI vectors, whose norms are reduced over the ranks. Serial: none.
  virtual std::optional<VectorDistribution> distribution() const { return std::nullopt; }

  // Checkpoints: a system whose evaluation depends on more than its arguments (a neighbour list
  // kept between rebuilds, a load history) saves and restores that here; the integrator calls
  // these from its own saveState / restoreState. Most systems are functions of their arguments:
  // nothing to keep.
  virtual void saveState(StateArchive& archive) const { (void)archive; }
  virtual void restoreState(const StateArchive& archive) { (void)archive; }
};

}  // namespace mfwave
