#pragma once
// A read-only view of the per-particle fields one evaluation works on: positions, velocities and
// deviatoric stresses straight from the state vector y (particle-major), the current densities
// (from y, or the summation densities of this evaluation), the masses and, for the rate passes,
// the pair table of this evaluation (PairTable.hpp: the pairs inside the support with grad W and W,
// computed once and read by every pass; each pass visits every unordered pair once, PairSweep.hpp).
// The pair passes take this instead of the system, so each pass is a plain function of its inputs.

#include "core/Types.hpp"
#include "kernels/Kernel.hpp"
#include "methods/updated_lagrangian_sph/AlwaysInline.hpp"
#include "methods/updated_lagrangian_sph/PairTable.hpp"
#include "neighbours/NeighbourList.hpp"

namespace mfwave {

template <int D>
struct ParticleView {
  static constexpr int stressComponents = D * (D + 1) / 2;

  Index count = 0;
  const Kernel* kernel = nullptr;
  const NeighbourList* neighbours = nullptr;
  const Real* x = nullptr;    // count * D positions
  const Real* v = nullptr;    // count * D velocities
  const Real* s = nullptr;    // count * stressComponents, Voigt order
  const Real* rho = nullptr;  // count densities
  const Real* m = nullptr;    // count masses
  // The pairs inside the support with their kernel terms; set by the system for the rate passes.
  const PairTable* pairs = nullptr;
  // V_j = m_j / rho_j of this evaluation; set by the system for the rate passes.
  const Real* volume = nullptr;
  // The kernel-gradient correction C_i per particle (KernelGradientCorrection.hpp); null: none.
  const Mat<D>* correction = nullptr;

  Vec<D> position(Index i) const { return Eigen::Map<const Vec<D>>(x + i * D); }
  Vec<D> velocity(Index i) const { return Eigen::Map<const Vec<D>>(v + i * D); }
  // grad_i W_ij as particle i's rows use it: corrected when the view carries corrections.
  Vec<D> correctedGradient(Index i, const Vec<D>& gradW) const {
    return correction != nullptr ? Vec<D>(correction[i] * gradW) : gradW;
  }
};

}  // namespace mfwave
