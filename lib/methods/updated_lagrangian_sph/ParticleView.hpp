#pragma once
// A read-only view of the per-particle fields one evaluation works on: positions, velocities and
// deviatoric stresses straight from the state vector y (particle-major), the current densities
// (from y, or the summation densities of this evaluation), the masses and, for the rate passes,
// the pair table of this evaluation (PairTable.hpp: the pairs inside the support with grad W and W,
// computed once and read by every pass). The pair passes take this instead of the system, so each
// pass is a plain function of its inputs.

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
  // Calls pair(k, j, r, gradW) for every pair of row i inside the support, in list order (the same
  // order in every pass): k the pair table's entry, j the neighbour, r = x_i - x_j and
  // gradW = grad_i W_ij = F_ij r from the table. The loop every rate pass runs.
  template <class Pair>
  MFWAVE_ALWAYS_INLINE void forEachPair(Index i, Pair&& pair) const {
    const Vec<D> xi = position(i);
    const Index* indices = neighbours->indices.data();
    const std::uint8_t* inside = pairs->inside.data();
    const Real* factor = pairs->gradientFactor.data();
    const Index last = neighbours->offsets[static_cast<std::size_t>(i) + 1];
    for (Index k = neighbours->offsets[static_cast<std::size_t>(i)]; k < last; ++k) {
      if (inside[k] == 0) continue;  // i itself, or listed through the skin but outside the support
      const Index j = indices[k];
      const Vec<D> r = xi - position(j);
      pair(k, j, r, Vec<D>(factor[k] * r));
    }
  }
};

}  // namespace mfwave
