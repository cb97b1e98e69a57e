#pragma once
// What a total-Lagrangian SPH evaluation needs of the reference configuration, computed once:
// for each particle i its volume V_i, its kernel-gradient correction B_i and, row by row, its
// neighbours j inside the kernel support (self excluded) with grad_i W(X_i - X_j).
//
// B_i = M_i^{-T}, M_i = sum_j V_j (X_j - X_i) grad_i W_ij^T, so that the corrected gradient
// sum_j V_j (f_j - f_i) (B_i grad_i W_ij)^T is exact for linear f (Randles-Libersky, Bonet-Lok),
// also at free surfaces. With grad_i W_ij = w_ij (X_j - X_i), w_ij = -W'(r) / r >= 0, this
// corrected gradient is the least-squares fit that minimises
// sum_j V_j w_ij |f_j - f_i - G (X_j - X_i)|^2: the property the hourglass penalty rests on.

#include "core/Types.hpp"
#include "kernels/Kernel.hpp"
#include "particles/ParticleSet.hpp"

#include <functional>
#include <vector>

namespace mfwave {

template <int D>
struct ReferencePairs {
  std::vector<Real> X;            // count * D reference positions
  std::vector<Real> volume;       // V_i
  std::vector<Mat<D>> correction;  // B_i
  std::vector<Index> offsets;     // count + 1: row i is [offsets[i], offsets[i + 1])
  std::vector<Index> neighbour;   // j of each pair
  std::vector<Real> gradient;     // D per pair: grad_i W(X_i - X_j)

  Index count() const { return static_cast<Index>(volume.size()); }
  Index pairCount() const { return static_cast<Index>(neighbour.size()); }
};

// Throws InputError("particles") for ghosts, an empty set or a non-positive volume, and when a
// particle's moment matrix M_i is singular (fewer than D independent neighbours: a loose particle
// or a line of them), naming the particle. `interacts`, when given, keeps only the pairs (i, j) it
// accepts (a crack's visibility criterion).
template <int D>
ReferencePairs<D> makeReferencePairs(const ParticleSet<D>& particles, const Kernel& kernel,
                                     const std::function<bool(Index, Index)>& interacts = {});

extern template ReferencePairs<1> makeReferencePairs<1>(const ParticleSet<1>&, const Kernel&,
                                                        const std::function<bool(Index, Index)>&);
extern template ReferencePairs<2> makeReferencePairs<2>(const ParticleSet<2>&, const Kernel&,
                                                        const std::function<bool(Index, Index)>&);
extern template ReferencePairs<3> makeReferencePairs<3>(const ParticleSet<3>&, const Kernel&,
                                                        const std::function<bool(Index, Index)>&);

}  // namespace mfwave
