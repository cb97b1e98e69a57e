#pragma once
// The kernel terms of one evaluation's pairs, computed once and read by every pair pass (the
// kernel-gradient correction, the velocity-gradient pass and the force pass). Entries run parallel
// to the skinned neighbour lists (entry e of row i is the pair i, j = list.indices[e]); an entry is
// used when j != i and |x_i - x_j| < R (the lists also hold pairs up to (1 + skin) R), and then
// holds
//   F_ij = (dW/dr)(r_ij) / r_ij, so that grad_i W_ij = F_ij (x_i - x_j),  and W_ij (when asked for).
// The passes form x_i - x_j from the same positions, so F_ij (x_i - x_j) is what Kernel::gradient
// computes. F and W are symmetric in i, j: each is evaluated once per unordered pair, by the row of
// the smaller index, and stored in both entries through the mirror index (the position of i in row
// j, found once per list rebuild). Each entry is written by exactly one row, with the same value on
// any number of threads. The kernel is evaluated through its inline profile
// (kernels/KernelProfiles.hpp), with the same expressions as the virtual kernel. The storage is
// reused between evaluations (about 21 bytes per listed pair).

#include "core/Types.hpp"
#include "kernels/Kernel.hpp"
#include "neighbours/NeighbourList.hpp"

#include <cstdint>
#include <vector>

namespace mfwave {

struct PairTable {
  std::vector<std::uint8_t> inside;   // 1: the entry is a pair inside the support
  std::vector<Real> gradientFactor;   // F_ij
  std::vector<Real> value;            // W_ij; empty unless built with values
  std::vector<std::uint32_t> mirror;  // position of i in row j, for the entry (i, j)
  bool mirrorValid = false;           // false: the lists were rebuilt since the mirror was found

  bool used(Index e) const { return inside[static_cast<std::size_t>(e)] != 0; }
};

// Fills `table` for positions x (count * D, particle-major) over `list`. withValues: also W_ij.
// Call with table.mirrorValid = false after every rebuild of the lists.
template <int D>
void buildPairTable(const Kernel& kernel, const NeighbourList& list, const Real* x, Index count, bool withValues,
                    PairTable& table);

extern template void buildPairTable<1>(const Kernel&, const NeighbourList&, const Real*, Index, bool, PairTable&);
extern template void buildPairTable<2>(const Kernel&, const NeighbourList&, const Real*, Index, bool, PairTable&);
extern template void buildPairTable<3>(const Kernel&, const NeighbourList&, const Real*, Index, bool, PairTable&);

}  // namespace mfwave
