#pragma once
// A sum over the whole lattice, computed on the ranks and bitwise the serial one (issue 22).
// Serial sums over a lattice (energies, norms: sumOverLatticeNodes, LatticeSecondOrderSystem) add
// each lattice line along x in node order, then the lines in order. When every rank owns whole
// lines (a decomposition that keeps x whole), each rank's line sums are the serial ones; gathering
// them and adding them in the lattice's line order gives the serial total on every rank, whatever
// the rank count. The gather moves one value per line (8 bytes per n_x nodes): fine for energies
// at output intervals; a step-by-step reduction at 10^9 nodes would want a fixed-shape tree.

#include "core/Types.hpp"
#include "decomposition/BlockDecomposition.hpp"

#include <mpi.h>

#include <vector>

namespace mfwave {

// `ownedLineSums`: one per line of this rank's block, in the block's order (x fastest over the
// other axes). Throws Error when the decomposition splits x.
template <int D>
Real sumInLatticeOrder(const BlockDecomposition<D>& decomposition, int rank, const std::vector<Real>& ownedLineSums,
                       MPI_Comm communicator);

extern template Real sumInLatticeOrder<1>(const BlockDecomposition<1>&, int, const std::vector<Real>&, MPI_Comm);
extern template Real sumInLatticeOrder<2>(const BlockDecomposition<2>&, int, const std::vector<Real>&, MPI_Comm);
extern template Real sumInLatticeOrder<3>(const BlockDecomposition<3>&, int, const std::vector<Real>&, MPI_Comm);

}  // namespace mfwave
