#pragma once
// The rate passes' sweep over the pairs, each unordered pair evaluated once (issue 21). The
// velocity-gradient and force terms of a pair i, j are evaluated by the row of the smaller index
// and added to both rows: the pair force is antisymmetric, the density, viscous, pressure and
// artificial-stress work terms are symmetric and the velocity-gradient term is the same outer
// product with the other side's volume (and, with the correction, the other side's C). The
// equations are those of KinematicsPass.hpp and ForcePass.hpp.
//
// The order of the sums does not depend on the number of threads. The rows are cut into blocks of
// B consecutive indices, B = max(reach, 64), where reach is the largest j - i of a listed pair (a
// property of the lists, not of the threads; PairTable::blockSize, found once per list rebuild).
// Block b holds the pairs i < j with i in block b, so it writes only rows of blocks b and b + 1. The
// even blocks run first (in parallel: their rows do not meet), then the odd blocks; within a block
// the rows run in increasing i and each row's pairs in list order. Every row thus receives its
// terms in one fixed order: on 1 and on 2 threads the rates are the same bits. They differ from the
// former gather (each row summing all its pairs) by round-off only. The energy rate is summed per pair in the contracted form
//   -(s_i / rho_i^2) : m_j v_ij (C_i grad W)^T = m_j v_ji . (A_i C_i grad W) (+ P_i v_ji . grad W),
// which needs the per-pair products A_i grad W that the force forms anyway.
//
// Scratch: one PairSums per particle (13 values in 2-D, 20 in 3-D; 104 and 160 bytes), owned by
// the system and reused. The pair table holds the pairs j > i only (PairTable.hpp). Particles
// numbered without spatial order (a large reach) still give the same rates, but fewer blocks to
// share between threads (one block, one thread, when reach >= n / 2). The lists must be symmetric
// (j in row i exactly when i in row j), as radius searches give.

#include "methods/updated_lagrangian_sph/AlwaysInline.hpp"
#include "methods/updated_lagrangian_sph/ForcePass.hpp"
#include "methods/updated_lagrangian_sph/KinematicsPass.hpp"
#include "methods/updated_lagrangian_sph/KinematicsTerms.hpp"
#include "methods/updated_lagrangian_sph/PairSums.hpp"
#include "methods/updated_lagrangian_sph/ParallelThreshold.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace mfwave {


namespace pair_sweep {

// Calls row(i) for every particle, block by block (see above): the even blocks, in parallel, then
// the odd blocks. row(i) may write rows i..i + reach.
template <class Row>
void forEachRowInBlocks(const PairTable& table, Index n, const Row& row) {
  const Index size = table.blockSize;
  const Index blocks = (n + size - 1) / size;
#pragma omp parallel if (n > kParallelParticles)
  for (Index phase = 0; phase < 2; ++phase) {
    // The loop's implied barrier keeps the phases apart.
#pragma omp for schedule(static)
    for (Index b = phase; b < blocks; b += 2) {
      const Index last = std::min(n, (b + 1) * size);
      for (Index i = b * size; i < last; ++i) row(i);
    }
  }
}

template <int D, bool Kinematics, bool Force>
struct Sweep {
  const ParticleView<D>& view;
  bool xsph = false;
  const ForceInputs<D>* inputs = nullptr;
  PairSums<D>* sums = nullptr;

  // Row i's pairs with j > i.
  MFWAVE_ALWAYS_INLINE void row(Index i) const {
    const Index* indices = view.neighbours->indices.data();
    const std::uint8_t* inside = view.pairs->inside.data();
    const Real* factor = view.pairs->gradientFactor.data();
    const Real* smoothingWeight = xsph ? view.pairs->smoothingWeight.data() : nullptr;
    const bool corrected = view.correction != nullptr;
    const Mat<D>* C = view.correction;
    const Real* m = view.m;
    const Real* V = view.volume;
    const Index end = view.neighbours->offsets[static_cast<std::size_t>(i) + 1];
    const Index begin = view.pairs->first[static_cast<std::size_t>(i)];
    const Index entry = view.pairs->offsets[static_cast<std::size_t>(i)];
    const Vec<D> xi = view.position(i);
    const Vec<D> vi = view.velocity(i);
    const Real mi = m[i];
    const Real Vi = V[i];
    // Force inputs of row i.
    const bool viscous = Force && inputs->viscosity.active();
    const Real* stressWeight = Force && inputs->artificialStress != nullptr ? view.pairs->stressWeight.data() : nullptr;
    const Mat<D>* A = Force ? (inputs->correctedStressOverRho2 != nullptr ? inputs->correctedStressOverRho2
                                                                          : inputs->stressOverRho2)
                            : nullptr;
    const Real* P = Force ? inputs->pressureOverRho2 : nullptr;
    const Mat<D>* R = Force ? inputs->artificialStress : nullptr;
    const Real Pi = Force ? P[i] : 0.0;
    const bool forceCorrected = Force && inputs->correctedStressOverRho2 != nullptr;

    PairSums<D> own = sums[i];
    for (Index k = begin, e = entry; k < end; ++k, ++e) {
      if (inside[e] == 0) continue;  // listed through the skin but outside the support
      const Index j = indices[k];
      const Vec<D> r = xi - view.position(j);
      const Vec<D> g = factor[e] * r;  // grad_i W_ij; grad_j W_ji = -g
      const Vec<D> vji = view.velocity(j) - vi;
      const Real mj = m[j];
      PairSums<D>& other = sums[j];
      // With v_ij = -v_ji and grad_j W_ji = -g, row j's terms are written with v_ji and g.
      const Real d = vji.dot(g);  // v_ji . grad_i W_ij = v_ij . grad_j W_ji
      if constexpr (Kinematics) {
        if (corrected) {
          const Vec<D> gi = C[i] * g;
          const Vec<D> gj = C[j] * g;
          own.gradient.noalias() += (V[j] * vji) * gi.transpose();
          other.gradient.noalias() += (Vi * vji) * gj.transpose();
          own.densityRate -= mj * vji.dot(gi);
          other.densityRate -= mi * vji.dot(gj);
        } else {
          own.gradient.noalias() += (V[j] * vji) * g.transpose();
          other.gradient.noalias() += (Vi * vji) * g.transpose();
          own.densityRate -= mj * d;
          other.densityRate -= mi * d;
        }
        if (xsph) {
          const Real w = smoothingWeight[e];
          own.smoothing += (mj * w) * vji;
          other.smoothing -= (mi * w) * vji;
        }
      }
      if constexpr (Force) {
        Real pi = 0;
        if (viscous) {
          const ArtificialViscosity& viscosity = inputs->viscosity;
          const Real mu = viscosity.mu(-vji.dot(r), r.squaredNorm());
          if (mu != 0) {
            pi = viscosity.pi(mu, 0.5 * (inputs->soundSpeed[i] + inputs->soundSpeed[j]),
                              0.5 * (view.rho[i] + view.rho[j]));
            const Real size = std::abs(mu);
            own.largestMu = std::max(own.largestMu, size);
            other.largestMu = std::max(other.largestMu, size);
          }
        }
        // A_i (C_i) grad_i W_ij and A_j (C_j) grad_i W_ij: the stress force and the deviatoric work.
        const Vec<D> ai = A[i] * g;
        const Vec<D> aj = A[j] * g;
        Vec<D> force = ai + aj;
        force -= pi * g;
        if (stressWeight != nullptr) {
          const Vec<D> extra = stressWeight[e] * ((R[i] + R[j]) * g);
          force += extra;
          const Real work = -vji.dot(extra);  // v_ij . extra
          own.artificialWork += mj * work;
          other.artificialWork += mi * work;
        }
        own.acceleration += mj * force;
        other.acceleration -= mi * force;
        const Real viscousTerm = pi * d;
        own.viscousWork -= mj * viscousTerm;
        other.viscousWork -= mi * viscousTerm;
        if (forceCorrected) {
          // -A_i : m_j v_ij (C_i g)^T + 1/2 m_j Pi_ij v_ij . g
          const Real half = 0.5 * viscousTerm;
          own.energyRate += mj * (vji.dot(ai) - half);
          other.energyRate += mi * (vji.dot(aj) - half);
        } else {
          // -(A_i + P_i I) : m_j v_ij g^T + 1/2 m_j (P_i + P_j + Pi_ij) v_ij . g
          const Real Pj = P[j];
          const Real half = 0.5 * (Pi + Pj + pi) * d;
          own.energyRate += mj * (vji.dot(ai) + Pi * d - half);
          other.energyRate += mi * (vji.dot(aj) + Pj * d - half);
        }
      }
    }
    sums[i] = own;
  }
};

// Sums every pair once into sums (resized to the particle count and zeroed first).
template <int D, bool Kinematics, bool Force>
void sumPairs(const ParticleView<D>& view, bool xsph, const ForceInputs<D>* inputs, std::vector<PairSums<D>>& sums) {
  const Index n = view.count;
  sums.resize(static_cast<std::size_t>(n));
  PairSums<D>* data = sums.data();
#pragma omp parallel for if (n > kParallelParticles) schedule(static)
  for (Index i = 0; i < n; ++i) data[i] = PairSums<D>();
  const Sweep<D, Kinematics, Force> sweep{view, xsph, inputs, data};
  forEachRowInBlocks(*view.pairs, n, [&](Index i) MFWAVE_INLINE_LAMBDA { sweep.row(i); });
}

template <int D>
void writeKinematics(const ParticleView<D>& view, const PairSums<D>& sums, Index i, const KinematicsSettings& settings,
                     const UpdatedLagrangianSphLayout<D>& layout, Real* qdot) {
  KinematicsRow<D> row;
  row.gradient = sums.gradient;
  row.smoothing = sums.smoothing;
  row.densityRate = sums.densityRate;
  row.write(view, i, settings, layout, qdot);
}

template <int D>
void writeForce(const ParticleView<D>& view, const PairSums<D>& sums, Index i, const ForceOutputs<D>& outputs) {
  for (int a = 0; a < D; ++a) outputs.acceleration[i * D + a] = sums.acceleration[a];
  outputs.energyRate[i] = sums.energyRate - 0.5 * sums.artificialWork;
  outputs.viscousPower[i] = 0.5 * view.m[i] * sums.viscousWork;
  outputs.artificialStressPower[i] = 0.5 * view.m[i] * sums.artificialWork;
  outputs.largestMu[i] = sums.largestMu;
}

}  // namespace pair_sweep
}  // namespace mfwave
