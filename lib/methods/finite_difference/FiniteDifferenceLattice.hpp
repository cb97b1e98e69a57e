#pragma once
// The finite-difference wave (FiniteDifferenceWaveOperator.hpp) stored as lattice stencils: one
// scalar row per row type (LatticeStencils<D, 1>) instead of a sparse matrix of N rows, so a box of
// any size costs a few dozen stencils, and the same system splits over MPI ranks
// (lib/decomposition/mpi) with every row bitwise the serial one.
//
// The stencils are read off assembleFiniteDifferenceWave on the compact lattice of the row types,
// so that assembly stays the one definition of every row (fixed faces included: their nodes keep
// their mass and have no stiffness row or column, so they stay at rest unless loaded).

#include "core/Types.hpp"
#include "lattice/LatticeSecondOrderSystem.hpp"
#include "methods/finite_difference/FiniteDifferenceWaveOperator.hpp"
#include "systems/SparseLoads.hpp"

#include <array>
#include <vector>

namespace mfwave {

// rho u_tt = E Lap(u) on the box lattice of `nodes` (x fastest; the particles' numbering of
// makeLattice) with `loads` as nonzero entries (dof = node). Throws what the sparse assembly throws
// (InputError "spacing", "density", "modulus", "boundary" for a free face) and InputError("lattice")
// for an axis of fewer than one node.
template <int D>
LatticeSecondOrderSystem<D, 1> finiteDifferenceLatticeSystem(const std::array<Index, D>& nodes,
                                                             const FiniteDifferenceWaveOptions& options,
                                                             std::vector<SparseLoad> loads = {});

extern template LatticeSecondOrderSystem<1, 1> finiteDifferenceLatticeSystem<1>(const std::array<Index, 1>&,
                                                                                const FiniteDifferenceWaveOptions&,
                                                                                std::vector<SparseLoad>);
extern template LatticeSecondOrderSystem<2, 1> finiteDifferenceLatticeSystem<2>(const std::array<Index, 2>&,
                                                                                const FiniteDifferenceWaveOptions&,
                                                                                std::vector<SparseLoad>);
extern template LatticeSecondOrderSystem<3, 1> finiteDifferenceLatticeSystem<3>(const std::array<Index, 3>&,
                                                                                const FiniteDifferenceWaveOptions&,
                                                                                std::vector<SparseLoad>);

}  // namespace mfwave
