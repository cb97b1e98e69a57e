#pragma once
// A semi-discrete system of second order in time, u'' = a(t, u, u'), in the method-of-lines
// spirit: a spatial discretisation implements it, an integrator advances it, and neither knows
// the other. Integrators never see particles.

#include "core/StateArchive.hpp"
#include "core/Types.hpp"
#include "systems/VectorDistribution.hpp"

#include <optional>

namespace mfwave {

class SecondOrderSystem {
 public:
  virtual ~SecondOrderSystem() = default;

  // Number of unknowns (for a vector field on particles: particles * components).
  virtual Index size() const = 0;

  // The acceleration a = u'' at time t for displacement u and velocity v. All three have size().
  // Eigen::Ref lets callers pass whole vectors or views of foreign storage (the halves of
  // ARKODE's [u; v]) without copies.
  virtual void acceleration(Real t, Eigen::Ref<const Vector> u, Eigen::Ref<const Vector> v,
                            Eigen::Ref<Vector> a) = 0;

  // True if the acceleration depends on v (damping, dashpots, viscosity). Explicit integrators
  // use it to skip the velocity predictor when it is not needed.
  virtual bool dependsOnVelocity() const { return true; }

  // A system that holds one rank's share of the unknowns says so here (VectorDistribution.hpp), so
  // that integrators with global vector operations reduce them over the ranks. Serial: none.
  virtual std::optional<VectorDistribution> distribution() const { return std::nullopt; }

  // Checkpoints: a system whose evaluation depends on more than its arguments (a neighbour list
  // kept between rebuilds, a load history) saves and restores that here; the integrator calls
  // these from its own saveState / restoreState. Most systems are functions of their arguments:
  // nothing to keep.
  virtual void saveState(StateArchive& archive) const { (void)archive; }
  virtual void restoreState(const StateArchive& archive) { (void)archive; }
};

}  // namespace mfwave
