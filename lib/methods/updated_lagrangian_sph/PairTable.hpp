#pragma once
// The kernel terms of one evaluation's pairs, computed once and read by every pair pass (the
// kernel-gradient correction, the velocity-gradient pass and the force pass). Entries run parallel
// to the skinned neighbour lists (entry e of row i is the pair i, j = list.indices[e]); an entry is
// used when j != i and |x_i - x_j| < R (the lists also hold pairs up to (1 + skin) R), and then
// holds
//   F_ij = (dW/dr)(r_ij) / r_ij, so that grad_i W_ij = F_ij (x_i - x_j),
//   with XSPH the weight 2 W_ij / (rho_i + rho_j) (m_j times it is the XSPH weight of Monaghan 1989),
//   with the artificial stress f_ij^n = (W_ij / W(dp))^n (ArtificialStress.hpp).
// The passes form x_i - x_j from the same positions, so F_ij (x_i - x_j) is what Kernel::gradient
// computes. All three are symmetric in i, j: each is evaluated once per unordered pair, by the row of
// the smaller index, and stored in both entries through the mirror index (the position of i in row
// j, found once per list rebuild in one serial pass). Each entry is written by exactly one row, with
// the same value on any number of threads. The kernel is evaluated through its inline profile
// (kernels/KernelProfiles.hpp), with the same expressions as the virtual kernel. The storage is
// reused between evaluations (13 to 29 bytes per listed pair).

#include "core/Types.hpp"
#include "kernels/Kernel.hpp"
#include "neighbours/NeighbourList.hpp"

#include <cstdint>
#include <vector>

namespace mfwave {

struct PairTable {
  std::vector<std::uint8_t> inside;   // 1: the entry is a pair inside the support
  std::vector<Real> gradientFactor;   // F_ij
  std::vector<Real> smoothingWeight;  // 2 W_ij / (rho_i + rho_j); empty without XSPH
  std::vector<Real> stressWeight;     // f_ij^n; empty without the artificial stress
  std::vector<std::uint32_t> mirror;  // position of i in row j, for the entry (i, j)
  bool mirrorValid = false;           // false: the lists were rebuilt since the mirror was found
  std::vector<Index> mirrorScratch;   // per row, while the mirror is found

  bool used(Index e) const { return inside[static_cast<std::size_t>(e)] != 0; }
};

struct PairTableSettings {
  const Real* rho = nullptr;  // the densities of the evaluation; read with XSPH only
  bool xsph = false;
  bool artificialStress = false;
  Real inverseReferenceKernel = 0;  // 1 / W(dp)
  Real artificialStressExponent = 4;
};

// Fills `table` for positions x (count * D, particle-major) over `list`. Call with
// table.mirrorValid = false after every rebuild of the lists.
template <int D>
void buildPairTable(const Kernel& kernel, const NeighbourList& list, const Real* x, Index count,
                    const PairTableSettings& settings, PairTable& table);

extern template void buildPairTable<1>(const Kernel&, const NeighbourList&, const Real*, Index,
                                       const PairTableSettings&, PairTable&);
extern template void buildPairTable<2>(const Kernel&, const NeighbourList&, const Real*, Index,
                                       const PairTableSettings&, PairTable&);
extern template void buildPairTable<3>(const Kernel&, const NeighbourList&, const Real*, Index,
                                       const PairTableSettings&, PairTable&);

}  // namespace mfwave
