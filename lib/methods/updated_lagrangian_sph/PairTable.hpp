#pragma once
// The pairs of one evaluation with their kernel terms, computed once and read by every pair pass
// (the kernel-gradient correction, the velocity-gradient pass and the force pass): for each row i,
// the neighbours j != i of the skinned lists that lie inside the kernel support (the lists also
// hold pairs up to (1 + skin) R), in the lists' order, with
//   F_ij = (dW/dr)(r_ij) / r_ij, so that grad_i W_ij = F_ij (x_i - x_j),  and W_ij (when asked for).
// The passes form x_i - x_j from the same positions, so F_ij (x_i - x_j) is what Kernel::gradient
// computes. Stored structure-of-arrays in compressed rows (row i is [offsets[i], offsets[i + 1])),
// 16 or 24 bytes per pair; the storage is reused between evaluations. Rows are counted and filled
// independently, so the table does not depend on the thread count. The kernel is evaluated through
// its inline profile (kernels/KernelProfiles.hpp), with the same expressions as the virtual kernel.

#include "core/Types.hpp"
#include "kernels/Kernel.hpp"
#include "neighbours/NeighbourList.hpp"

#include <vector>

namespace mfwave {

struct PairTable {
  std::vector<Index> offsets;  // rows + 1 entries
  std::vector<Index> neighbour;
  std::vector<Real> gradientFactor;  // F_ij
  std::vector<Real> value;           // W_ij; empty unless built with values

  Index begin(Index i) const { return offsets[static_cast<std::size_t>(i)]; }
  Index end(Index i) const { return offsets[static_cast<std::size_t>(i) + 1]; }
  Index pairCount() const { return offsets.empty() ? 0 : offsets.back(); }
};

// Fills `table` for positions x (count * D, particle-major) over `list`. withValues: also W_ij.
template <int D>
void buildPairTable(const Kernel& kernel, const NeighbourList& list, const Real* x, Index count, bool withValues,
                    PairTable& table);

extern template void buildPairTable<1>(const Kernel&, const NeighbourList&, const Real*, Index, bool, PairTable&);
extern template void buildPairTable<2>(const Kernel&, const NeighbourList&, const Real*, Index, bool, PairTable&);
extern template void buildPairTable<3>(const Kernel&, const NeighbourList&, const Real*, Index, bool, PairTable&);

}  // namespace mfwave
