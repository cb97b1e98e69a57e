#pragma once
// A system driven by external loads it does not know of: u'' = a(t, u, u') + sum_l h_l(t) g_l, the
// g_l given per unknown as accelerations (force over the unknown's mass), as SparseLoads. It wraps a
// method that has no load of its own (the total-Lagrangian SPH) for a study that loads its surface.

#include "systems/SecondOrderSystem.hpp"
#include "systems/SparseLoads.hpp"

#include <utility>
#include <vector>

namespace mfwave {

class ForcedSecondOrderSystem final : public SecondOrderSystem {
 public:
  // `system` must outlive this one, and each load's history its load.
  ForcedSecondOrderSystem(SecondOrderSystem& system, std::vector<SparseLoad> accelerations)
      : system_(system), loads_(std::move(accelerations)) {}

  Index size() const override { return system_.size(); }
  void acceleration(Real t, Eigen::Ref<const Vector> u, Eigen::Ref<const Vector> v, Eigen::Ref<Vector> a) override {
    system_.acceleration(t, u, v, a);
    addSparseLoads(loads_, t, a.data());
  }
  bool dependsOnVelocity() const override { return system_.dependsOnVelocity(); }
  std::optional<VectorDistribution> distribution() const override { return system_.distribution(); }
  void saveState(StateArchive& archive) const override { system_.saveState(archive); }
  void restoreState(const StateArchive& archive) override { system_.restoreState(archive); }

 private:
  SecondOrderSystem& system_;
  std::vector<SparseLoad> loads_;
};

}  // namespace mfwave
