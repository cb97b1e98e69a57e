#pragma once
// The kernel terms of one evaluation's pairs, computed once and read by every pair pass (the
// kernel-gradient correction, the velocity-gradient pass and the force pass). The passes evaluate
// each unordered pair once, from the row of the smaller index (PairSweep.hpp), so the table holds
// the pairs j > i only: row i's entries offsets[i] .. offsets[i + 1] run parallel to the tail
// list.indices[first[i] ..] of its sorted neighbour row. An entry is used when |x_i - x_j| < R (the
// lists also hold pairs up to (1 + skin) R), and then holds
//   F_ij = (dW/dr)(r_ij) / r_ij, so that grad_i W_ij = F_ij (x_i - x_j),
//   with XSPH the weight 2 W_ij / (rho_i + rho_j) (m_j times it is the XSPH weight of Monaghan 1989),
//   with the artificial stress f_ij^n = (W_ij / W(dp))^n (ArtificialStress.hpp).
// The passes form x_i - x_j from the same positions, so F_ij (x_i - x_j) is what Kernel::gradient
// computes. Each entry is written by its row alone, with the same value on any number of threads.
// The kernel is evaluated through its inline profile (kernels/KernelProfiles.hpp), with the same
// expressions as the virtual kernel. The storage is reused between evaluations (9 to 25 bytes per
// listed unordered pair, and 16 bytes per particle).

#include "core/Types.hpp"
#include "kernels/Kernel.hpp"
#include "neighbours/NeighbourList.hpp"

#include <cstdint>
#include <vector>

namespace mfwave {

struct PairTable {
  std::vector<Index> first;           // per row: the list position of its first neighbour j > i
  std::vector<Index> offsets;         // per row + 1: where its entries start in the arrays below
  // The block size of the pair sweeps (PairSweep.hpp): max(64, the largest listed j - i).
  Index blockSize = 64;
  bool rowsValid = false;  // false: the lists were rebuilt since first, offsets and blockSize were found
  std::vector<std::uint8_t> inside;   // 1: the entry is a pair inside the support
  std::vector<Real> gradientFactor;   // F_ij
  std::vector<Real> smoothingWeight;  // 2 W_ij / (rho_i + rho_j); empty without XSPH
  std::vector<Real> stressWeight;     // f_ij^n; empty without the artificial stress
};

struct PairTableSettings {
  const Real* rho = nullptr;  // the densities of the evaluation; read with XSPH only
  bool xsph = false;
  bool artificialStress = false;
  Real inverseReferenceKernel = 0;  // 1 / W(dp)
  Real artificialStressExponent = 4;
};

// Fills `table` for positions x (count * D, particle-major) over `list` (its rows sorted). Call
// with table.rowsValid = false after every rebuild of the lists.
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
