#include "decomposition/mpi/LineSums.hpp"

#include "core/Error.hpp"

#include <string>

namespace mfwave {

namespace {

// The lines of a box: the box with x collapsed to its first node.
template <int D>
Box<D> linesOf(Box<D> box) {
  box.hi[0] = box.lo[0] + 1;
  return box;
}

}  // namespace

template <int D>
Real sumInLatticeOrder(const BlockDecomposition<D>& decomposition, int rank, const std::vector<Real>& ownedLineSums,
                       MPI_Comm communicator) {
  if (decomposition.grid()[0] != 1)
    throw Error("sumInLatticeOrder: the decomposition splits x into " + std::to_string(decomposition.grid()[0]) +
                " blocks; a sum in the serial order needs whole lattice lines on every rank");
  const int ranks = decomposition.ranks();
  std::vector<int> counts(static_cast<std::size_t>(ranks)), offsets(static_cast<std::size_t>(ranks) + 1, 0);
  for (int q = 0; q < ranks; ++q) {
    counts[static_cast<std::size_t>(q)] = static_cast<int>(linesOf(decomposition.block(q)).count());
    offsets[static_cast<std::size_t>(q) + 1] = offsets[static_cast<std::size_t>(q)] + counts[static_cast<std::size_t>(q)];
  }
  if (static_cast<int>(ownedLineSums.size()) != counts[static_cast<std::size_t>(rank)])
    throw Error("sumInLatticeOrder: rank " + std::to_string(rank) + " gave " + std::to_string(ownedLineSums.size()) +
                " line sums for a block of " + std::to_string(counts[static_cast<std::size_t>(rank)]) + " lines");
  std::vector<Real> gathered(static_cast<std::size_t>(offsets.back()));
  const int code = MPI_Allgatherv(ownedLineSums.data(), counts[static_cast<std::size_t>(rank)], MPI_DOUBLE, gathered.data(),
                                  counts.data(), offsets.data(), MPI_DOUBLE, communicator);
  if (code != MPI_SUCCESS) throw Error("sumInLatticeOrder: MPI_Allgatherv failed with MPI error " + std::to_string(code));
  // Each rank's lines into their place in the lattice's order, then the serial sum.
  Box<D> all;
  all.hi = decomposition.nodes();
  const Box<D> lines = linesOf(all);
  std::vector<Real> inOrder(static_cast<std::size_t>(lines.count()), 0.0);
  for (int q = 0; q < ranks; ++q) {
    const Real* values = gathered.data() + offsets[static_cast<std::size_t>(q)];
    linesOf(decomposition.block(q)).forEachNode([&](const std::array<Index, D>& line) {
      inOrder[static_cast<std::size_t>(lines.localIndex(line))] = *values++;
    });
  }
  Real sum = 0;
  for (Real s : inOrder) sum += s;
  return sum;
}

template Real sumInLatticeOrder<1>(const BlockDecomposition<1>&, int, const std::vector<Real>&, MPI_Comm);
template Real sumInLatticeOrder<2>(const BlockDecomposition<2>&, int, const std::vector<Real>&, MPI_Comm);
template Real sumInLatticeOrder<3>(const BlockDecomposition<3>&, int, const std::vector<Real>&, MPI_Comm);

}  // namespace mfwave
