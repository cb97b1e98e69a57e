#pragma once
// The conservative smoothing of Ding-Long-Wu eq. (33), applied to the velocity after each step:
//   U^a <- U^a + alpha [ sum_b U^b W_ab V_b / sum_b W_ab V_b - U^a ],
// sums over the physical neighbours b of a (a included). With S_ab = W_ab V_b / sum_c W_ac V_c the
// row-stochastic smoothing matrix this is v <- v + alpha (S v - v), per velocity component.
//
// Why a rate: the paper gives alpha per step (0.1) but not the step, so a fixed alpha makes the
// damping depend on dt. The filter here holds a rate r per unit time and uses
// alpha_step = 1 - exp(-r dt): a mode with S-eigenvalue lambda then decays like
// exp(-r (1 - lambda) t) up to O(dt) (exactly for lambda = 0 and lambda = 1).
//
// What it conserves: with m_a = V_a / alpha_a = V_a sum_b W_ab V_b (alpha_a of eq. (29)),
// m_a S_ab = V_a W_ab V_b is symmetric, so sum_a m_a S_ab = m_b and the momentum
// sum_a (rho / alpha_a) V_a v_a (the lumped mass rho / alpha_a times the volume) is exact. The
// momentum with the plain volumes, sum_a rho V_a v_a, is not conserved near the boundary.
//
// Order 2 applies v <- v - alpha (I - S)^2 v instead: the same matrix, but a smooth mode with
// 1 - lambda = O((kh)^2) is damped at O((kh)^4), while grid-scale modes (1 - lambda = O(1)) are
// damped almost as strongly as by order 1. It is the weak stabilising filter of the consistent
// variant, whose non-symmetric boundary rows have slowly growing modes.

#include "core/Types.hpp"
#include "kernels/Kernel.hpp"
#include "neighbours/NeighbourList.hpp"
#include "particles/ParticleSet.hpp"

#include <functional>
#include <vector>

namespace mfwave {

// A scalar N x N matrix over the physical particles, stored by rows so that one row (a probe) is
// cheap and a product streams over the neighbour pattern.
using ParticleMatrix = Eigen::SparseMatrix<Real, Eigen::RowMajor, int>;

// S of eq. (33): S_ab = W_ab V_b / sum_c W_ac V_c over the physical neighbours (ghosts carry no
// unknowns), rows summing to 1. `volumes` holds V_b of the physical particles. Assembled with
// OpenMP into a precomputed row layout, so the result does not depend on the number of threads.
// Throws InputError("volumes") for a wrong length (and the checks of checkVeryWeakInputs).
template <int D>
ParticleMatrix smoothingMatrix(const ParticleSet<D>& particles, const NeighbourList& neighbours,
                               const Kernel& kernel, const std::vector<Real>& volumes);

// out = matrix applied to each component of an interleaved field (dof = particle * dimension +
// component). `out` is resized if needed and must not alias `in`. Throws InputError("field") when
// the length does not match.
void multiplyComponents(const ParticleMatrix& matrix, const Vector& in, int dimension, Vector& out);

class ConservativeSmoothing {
 public:
  // Throws InputError("smoothing.rate") unless rate >= 0 and finite, InputError("dimension")
  // unless 1 <= dimension <= 3, InputError("smoothing.matrix") unless the matrix is square,
  // InputError("smoothing.order") unless order is 1 (eq. 33) or 2.
  ConservativeSmoothing(ParticleMatrix matrix, int dimension, Real rate, int order = 1);
  // The same filter with S given by its product on interleaved fields, out = (S x I) in (the
  // lattice storage's stencils), over `particles` particles. Throws as above.
  using ComponentProduct = std::function<void(const Vector& in, Vector& out)>;
  ConservativeSmoothing(ComponentProduct product, Index particles, int dimension, Real rate, int order = 1);

  // alpha_step = 1 - exp(-rate dt). Throws InputError("smoothing.rate") / InputError("time_step").
  static Real stepFraction(Real rate, Real dt);
  // The rate whose step fraction at dt is alpha (0 <= alpha < 1): -ln(1 - alpha) / dt. The paper's
  // alpha = 0.1 per step at dt is rate 0.10536 / dt. Throws InputError("smoothing.alpha") /
  // InputError("time_step").
  static Real rateFromStepFraction(Real alpha, Real dt);

  // velocity <- velocity + alpha_step (S velocity - velocity), per component (interleaved). A rate
  // of zero leaves it untouched. Fits the integrator's velocity filter:
  //   integrator.setVelocityFilter([&smoothing](Real dt, Vector& v) { smoothing.apply(dt, v); });
  // Reuses an internal work buffer, so one object must not be applied from two threads at once.
  // Throws InputError("velocity") for a wrong length and InputError("time_step") for dt <= 0.
  void apply(Real dt, Vector& velocity) const;

  // Empty when S was given by its product.
  const ParticleMatrix& matrix() const { return matrix_; }
  int dimension() const { return dimension_; }
  Real rate() const { return rate_; }
  int order() const { return order_; }

 private:
  void multiply(const Vector& in, Vector& out) const;

  ParticleMatrix matrix_;
  ComponentProduct product_;
  Index particles_;
  int dimension_;
  Real rate_;
  int order_;
  mutable Vector work_, difference_;
};

}  // namespace mfwave
