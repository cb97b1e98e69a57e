#pragma once
// Samples of linear functionals of the collocation field u^h = sum_J psi_J d_J (a probe's component
// at a point, or along a direction) at every step without a solve. With d = C^{-1} [U; b_B(t)] and
// d' = C^{-1} [V; b_B'(t)] (ConstrainedCollocationSystem) a sample r . d would cost a solve with the
// constraint matrix; instead each row r is carried over to the right-hand side once, g = C^{-T} r
// (constraintAdjoint), and a sample is g . [U; b_B(t)] (or g . [V; b_B'(t)] for the rate).

#include "methods/collocation/ConstrainedCollocationSystem.hpp"

#include <vector>

namespace mfwave {

class CollocationSampler {
 public:
  // `functionals`: system.system().cols() rows, one column r_i per sample. Square C only (throws
  // mfwave::Error for least squares, as constraintAdjoint does).
  CollocationSampler(const ConstrainedCollocationSystem& system, const Eigen::MatrixXd& functionals);

  // r_i . d at time t for every i: from the displacement state U, or r_i . d' from the velocity
  // state V where rate[i] (b_B and b_B' are evaluated only when some sample needs them).
  std::vector<Real> sample(Real t, const Vector& U, const Vector& V, const std::vector<bool>& rate) const;
  Index size() const { return adjoint_.cols(); }

 private:
  const ConstrainedCollocationSystem& system_;
  Eigen::MatrixXd adjoint_;  // column i: C^{-T} r_i
};

}  // namespace mfwave
