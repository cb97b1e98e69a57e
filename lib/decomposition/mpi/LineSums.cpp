#include "decomposition/mpi/LineSums.hpp"

#include "core/Error.hpp"

#include <string>

namespace mfwave {

namespace {

// The chain's messages (running line sums from one x-piece to the next), apart from the halo's.
constexpr int kRunningSumsTag = 0x4c53;

// The lattice lines whose sums a block ends: the block's lines (x collapsed to the lattice's first
// node) when it holds the last x-piece of its lines, none otherwise.
template <int D>
Box<D> linesEndedBy(const BlockDecomposition<D>& decomposition, int rank) {
  Box<D> box = decomposition.block(rank);
  if (box.hi[0] != decomposition.nodes()[0]) return Box<D>{};
  box.lo[0] = 0;
  box.hi[0] = 1;
  return box;
}

// Every rank's ended line sums gathered, put in the lattice's line order and added in it: the
// serial total, on every rank.
template <int D>
Real addEndedLinesInLatticeOrder(const BlockDecomposition<D>& decomposition, int rank,
                                 const std::vector<Real>& endedLineSums, MPI_Comm communicator) {
  const int ranks = decomposition.ranks();
  std::vector<int> counts(static_cast<std::size_t>(ranks)), offsets(static_cast<std::size_t>(ranks) + 1, 0);
  for (int q = 0; q < ranks; ++q) {
    counts[static_cast<std::size_t>(q)] = static_cast<int>(linesEndedBy(decomposition, q).count());
    offsets[static_cast<std::size_t>(q) + 1] = offsets[static_cast<std::size_t>(q)] + counts[static_cast<std::size_t>(q)];
  }
  if (static_cast<int>(endedLineSums.size()) != counts[static_cast<std::size_t>(rank)])
    throw Error("sumInLatticeOrder: rank " + std::to_string(rank) + " gave " + std::to_string(endedLineSums.size()) +
                " line sums for a block that ends " + std::to_string(counts[static_cast<std::size_t>(rank)]) + " lines");
  std::vector<Real> gathered(static_cast<std::size_t>(offsets.back()));
  const int code = MPI_Allgatherv(endedLineSums.data(), counts[static_cast<std::size_t>(rank)], MPI_DOUBLE,
                                  gathered.data(), counts.data(), offsets.data(), MPI_DOUBLE, communicator);
  if (code != MPI_SUCCESS) throw Error("sumInLatticeOrder: MPI_Allgatherv failed with MPI error " + std::to_string(code));
  // Each rank's lines into their place in the lattice's order, then the serial sum.
  Box<D> lines;
  lines.hi = decomposition.nodes();
  lines.hi[0] = 1;
  std::vector<Real> inOrder(static_cast<std::size_t>(lines.count()), 0.0);
  for (int q = 0; q < ranks; ++q) {
    const Real* values = gathered.data() + offsets[static_cast<std::size_t>(q)];
    linesEndedBy(decomposition, q).forEachNode([&](const std::array<Index, D>& line) {
      inOrder[static_cast<std::size_t>(lines.localIndex(line))] = *values++;
    });
  }
  Real sum = 0;
  for (Real s : inOrder) sum += s;
  return sum;
}

// This rank's piece of its lines' serial sums: the running sums from the x-predecessor (+0 for the
// first piece, as the serial sum starts), this block's terms added node by node along x, the result
// passed to the x-successor. Returns the running sums after this piece, one per owned line.
template <int D>
std::vector<Real> runningLineSums(const BlockDecomposition<D>& decomposition, int rank, const std::vector<Real>& nodeTerms,
                                  int termsPerNode, MPI_Comm communicator) {
  const Box<D> own = decomposition.block(rank);
  const std::array<int, D> position = decomposition.gridPosition(rank);
  const int lines = static_cast<int>(own.lineCount());
  std::vector<Real> running(static_cast<std::size_t>(lines), 0.0);
  std::array<int, D> neighbour = position;
  if (position[0] > 0) {
    neighbour[0] = position[0] - 1;
    const int code = MPI_Recv(running.data(), lines, MPI_DOUBLE, decomposition.rankAt(neighbour), kRunningSumsTag,
                              communicator, MPI_STATUS_IGNORE);
    if (code != MPI_SUCCESS) throw Error("sumInLatticeOrder: MPI_Recv failed with MPI error " + std::to_string(code));
  }
  const Index termsPerLine = termsPerNode * own.extent(0);
  for (Index line = 0; line < lines; ++line) {
    Real sum = running[static_cast<std::size_t>(line)];
    const Real* terms = nodeTerms.data() + line * termsPerLine;
    for (Index t = 0; t < termsPerLine; ++t) sum += terms[t];
    running[static_cast<std::size_t>(line)] = sum;
  }
  if (position[0] + 1 < decomposition.grid()[0]) {
    neighbour[0] = position[0] + 1;
    const int code = MPI_Send(running.data(), lines, MPI_DOUBLE, decomposition.rankAt(neighbour), kRunningSumsTag,
                              communicator);
    if (code != MPI_SUCCESS) throw Error("sumInLatticeOrder: MPI_Send failed with MPI error " + std::to_string(code));
  }
  return running;
}

}  // namespace

template <int D>
Real sumInLatticeOrder(const BlockDecomposition<D>& decomposition, int rank, const std::vector<Real>& ownedLineSums,
                       MPI_Comm communicator) {
  if (decomposition.grid()[0] != 1)
    throw Error("sumInLatticeOrder: the decomposition splits x into " + std::to_string(decomposition.grid()[0]) +
                " blocks; sums of whole lines need whole lattice lines on every rank (sumNodeTermsInLatticeOrder "
                "takes a split x)");
  return addEndedLinesInLatticeOrder<D>(decomposition, rank, ownedLineSums, communicator);
}

template <int D>
Real sumNodeTermsInLatticeOrder(const BlockDecomposition<D>& decomposition, int rank, const std::vector<Real>& nodeTerms,
                                int termsPerNode, MPI_Comm communicator) {
  const Index expected = termsPerNode * decomposition.block(rank).count();
  if (termsPerNode < 1 || static_cast<Index>(nodeTerms.size()) != expected)
    throw Error("sumNodeTermsInLatticeOrder: rank " + std::to_string(rank) + " gave " +
                std::to_string(nodeTerms.size()) + " terms, " + std::to_string(termsPerNode) +
                " per node of its block, " + std::to_string(expected) + " in all");
  std::vector<Real> running = runningLineSums<D>(decomposition, rank, nodeTerms, termsPerNode, communicator);
  if (linesEndedBy(decomposition, rank).empty()) running.clear();  // not the lines' last piece
  return addEndedLinesInLatticeOrder<D>(decomposition, rank, running, communicator);
}

template Real sumInLatticeOrder<1>(const BlockDecomposition<1>&, int, const std::vector<Real>&, MPI_Comm);
template Real sumInLatticeOrder<2>(const BlockDecomposition<2>&, int, const std::vector<Real>&, MPI_Comm);
template Real sumInLatticeOrder<3>(const BlockDecomposition<3>&, int, const std::vector<Real>&, MPI_Comm);
template Real sumNodeTermsInLatticeOrder<1>(const BlockDecomposition<1>&, int, const std::vector<Real>&, int, MPI_Comm);
template Real sumNodeTermsInLatticeOrder<2>(const BlockDecomposition<2>&, int, const std::vector<Real>&, int, MPI_Comm);
template Real sumNodeTermsInLatticeOrder<3>(const BlockDecomposition<3>&, int, const std::vector<Real>&, int, MPI_Comm);

}  // namespace mfwave
