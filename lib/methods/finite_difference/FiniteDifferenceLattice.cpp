#include "methods/finite_difference/FiniteDifferenceLattice.hpp"

#include "core/Error.hpp"
#include "neighbours/CellList.hpp"
#include "neighbours/NeighbourList.hpp"
#include "particles/Lattice.hpp"

#include <string>

namespace mfwave {

template <int D>
LatticeSecondOrderSystem<D, 1> finiteDifferenceLatticeSystem(const std::array<Index, D>& nodes,
                                                             const FiniteDifferenceWaveOptions& options,
                                                             std::vector<SparseLoad> loads) {
  for (int a = 0; a < D; ++a)
    if (nodes[static_cast<std::size_t>(a)] < 1)
      throw InputError("lattice", "axis " + std::to_string(a) + " has " + std::to_string(nodes[static_cast<std::size_t>(a)]) +
                                      " nodes");
  if (!(options.spacing > 0)) throw InputError("spacing", "must be positive");
  // The stencil reaches one node, but a row next to a fixed face lacks that face's column: the rows
  // differ up to two nodes from a face (depth 2).
  const LatticeRowTypes<D> types(nodes, 2);
  Vec<D> upper;
  for (int a = 0; a < D; ++a)
    upper[a] = static_cast<Real>(types.compactNodes()[static_cast<std::size_t>(a)] - 1) * options.spacing;
  const ParticleSet<D> compact = makeLattice<D>(Vec<D>::Zero(), upper, options.spacing);
  const NeighbourList neighbours = buildNeighbourList(CellList<D>(compact, 1.5 * options.spacing));
  const LinearSecondOrderSystem sparse = assembleFiniteDifferenceWave<D>(compact, neighbours, options);
  return LatticeSecondOrderSystem<D, 1>(LatticeStencils<D, 1>(types, sparse.mass()), LatticeStencils<D, 1>(),
                                        LatticeStencils<D, 1>(types, sparse.stiffness()), std::move(loads));
}

template LatticeSecondOrderSystem<1, 1> finiteDifferenceLatticeSystem<1>(const std::array<Index, 1>&,
                                                                         const FiniteDifferenceWaveOptions&,
                                                                         std::vector<SparseLoad>);
template LatticeSecondOrderSystem<2, 1> finiteDifferenceLatticeSystem<2>(const std::array<Index, 2>&,
                                                                         const FiniteDifferenceWaveOptions&,
                                                                         std::vector<SparseLoad>);
template LatticeSecondOrderSystem<3, 1> finiteDifferenceLatticeSystem<3>(const std::array<Index, 3>&,
                                                                         const FiniteDifferenceWaveOptions&,
                                                                         std::vector<SparseLoad>);

}  // namespace mfwave
