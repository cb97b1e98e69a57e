#pragma once
// Views a second-order system u'' = a(t, u, u') as the first-order system y = [u; v],
// y' = [v; a(t, u, v)], so first-order integrators (ARKODE) can drive any second-order method.

#include "systems/FirstOrderSystem.hpp"
#include "systems/SecondOrderSystem.hpp"

namespace mfwave {

class SecondOrderAsFirstOrder : public FirstOrderSystem {
 public:
  explicit SecondOrderAsFirstOrder(SecondOrderSystem& system);

  Index size() const override { return 2 * system_.size(); }
  void rhs(Real t, Eigen::Ref<const Vector> y, Eigen::Ref<Vector> ydot) override;
  // The second-order system's distribution with twice its length: each rank holds [u; v] of its
  // own dofs, so the global y is a permutation of the serial [u; v] (the same element-wise
  // operations; norms summed in another order).
  std::optional<VectorDistribution> distribution() const override;

  // Pack u and v into y = [u; v], and split y back.
  Vector pack(const Vector& u, const Vector& v) const;
  void unpack(const Vector& y, Vector& u, Vector& v) const;

 private:
  SecondOrderSystem& system_;
};

}  // namespace mfwave
