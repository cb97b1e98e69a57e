#pragma once
// A sum over the whole lattice, computed on the ranks and bitwise the serial one (issue 22).
// Serial sums over a lattice (energies, norms: sumOverLatticeNodes, LatticeSecondOrderSystem) add
// each lattice line along x in node order, starting from +0, then the lines in order. Floating-point
// addition is not associative, so the ranks must add the same terms in the same order:
// - x whole (every rank owns whole lines): each rank's line sums are the serial ones; gathering
//   them and adding them in the lattice's line order gives the serial total on every rank;
// - x split: the ranks of one x-row of the rank grid hold pieces of the same lines. Piece k goes on
//   from the running sums piece k - 1 leaves (one message with a value per line from its
//   x-predecessor), adds its nodes' terms in x order and passes the running sums to its
//   x-successor; the last piece's running sums are the line sums, gathered as above. The pieces
//   add one after the other, but only additions wait: the terms are computed beforehand.
// The gather moves one value per line (8 bytes per n_x nodes): fine for energies at output
// intervals; a step-by-step reduction at 10^9 nodes would want a fixed-shape tree.

#include "core/Types.hpp"
#include "decomposition/BlockDecomposition.hpp"

#include <mpi.h>

#include <vector>

namespace mfwave {

// `ownedLineSums`: one per line of this rank's block, in the block's order (x fastest over the
// other axes), each the whole line's serial sum. Throws Error when the decomposition splits x.
template <int D>
Real sumInLatticeOrder(const BlockDecomposition<D>& decomposition, int rank, const std::vector<Real>& ownedLineSums,
                       MPI_Comm communicator);

// Any decomposition: `nodeTerms` holds `termsPerNode` terms per node of this rank's block, in the
// block's order (x fastest), each node's terms in the order the serial sum adds them; a term the
// serial sum does not add is -0.0 (x + (-0.0) = x for every x). Collective over the communicator;
// the x-pieces of a line add one after the other.
template <int D>
Real sumNodeTermsInLatticeOrder(const BlockDecomposition<D>& decomposition, int rank, const std::vector<Real>& nodeTerms,
                                int termsPerNode, MPI_Comm communicator);

// The sum the callers use: `terms(add)` must call add(k, j, term) for the j-th term (j <
// termsPerNode) of owned node k (the block's order) that the serial sum adds, each line's terms
// in the serial order (node by node along x, j ascending); lines may run on threads. With x whole
// the terms go straight into line sums (no per-node buffer, no extra messages); with x split they
// are stored first, so that every collective the terms need (a halo exchange) is over before the
// pieces of a line wait on one another.
template <int D, class Terms>
Real sumInLatticeOrder(const BlockDecomposition<D>& decomposition, int rank, int termsPerNode, Terms&& terms,
                       MPI_Comm communicator) {
  const Box<D> own = decomposition.block(rank);
  if (decomposition.grid()[0] == 1) {
    const Index nx = own.extent(0);
    std::vector<Real> lineSums(static_cast<std::size_t>(own.lineCount()), 0.0);
    terms([&](Index k, int, Real term) { lineSums[static_cast<std::size_t>(k / nx)] += term; });
    return sumInLatticeOrder<D>(decomposition, rank, lineSums, communicator);
  }
  std::vector<Real> nodeTerms(static_cast<std::size_t>(termsPerNode * own.count()), -0.0);
  terms([&](Index k, int j, Real term) { nodeTerms[static_cast<std::size_t>(termsPerNode * k + j)] = term; });
  return sumNodeTermsInLatticeOrder<D>(decomposition, rank, nodeTerms, termsPerNode, communicator);
}

extern template Real sumInLatticeOrder<1>(const BlockDecomposition<1>&, int, const std::vector<Real>&, MPI_Comm);
extern template Real sumInLatticeOrder<2>(const BlockDecomposition<2>&, int, const std::vector<Real>&, MPI_Comm);
extern template Real sumInLatticeOrder<3>(const BlockDecomposition<3>&, int, const std::vector<Real>&, MPI_Comm);
extern template Real sumNodeTermsInLatticeOrder<1>(const BlockDecomposition<1>&, int, const std::vector<Real>&, int,
                                                   MPI_Comm);
extern template Real sumNodeTermsInLatticeOrder<2>(const BlockDecomposition<2>&, int, const std::vector<Real>&, int,
                                                   MPI_Comm);
extern template Real sumNodeTermsInLatticeOrder<3>(const BlockDecomposition<3>&, int, const std::vector<Real>&, int,
                                                   MPI_Comm);

}  // namespace mfwave
