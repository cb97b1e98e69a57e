// The cost of one halo exchange (lib/decomposition/mpi/HaloExchange), run under mpirun:
//
//   mpirun -np 2 build/release/benchmarks/mpi/halo_exchange_cost [reach] [n ...]
//
// (as root with OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 in the environment).
//
// For cubes of n^3 lattice nodes with 3 values per node (a displacement field), decomposed over
// the ranks as a study would be: per rank the halo nodes, the bytes and messages sent per
// exchange, and the wall time of an exchange (the slowest rank's mean over repeated exchanges,
// after a warm-up), with the bandwidth that implies. Rank 0 prints a Markdown table
// (docs/scaling.md shows it). The smallest cube measures the latency of a near-empty exchange.
#include "MpiArguments.hpp"
#include "decomposition/mpi/HaloExchange.hpp"

#include <mpi.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

using namespace mfwave;

namespace {

struct Figures {
  Index haloNodes = 0;
  std::size_t bytes = 0;
  int messages = 0;
  double seconds = 0;
};

Figures measure(Index n, Index reach, int rank, int ranks) {
  const LatticeRowTypes<3> types({n, n, n}, std::max<Index>(1, reach));
  const BlockDecomposition<3> decomposition(types, ranks);
  HaloExchange<3> exchange(HaloPlan<3>(decomposition, rank, {reach, reach, reach}), 3, MPI_COMM_WORLD);
  std::vector<Real> local(static_cast<std::size_t>(exchange.localSize()), 1.0);
  for (int k = 0; k < 5; ++k) exchange.exchange(local.data());  // warm-up: connections, pages
  // Enough repeats for about 0.2 s at the first guess of the cost, at least 10.
  MPI_Barrier(MPI_COMM_WORLD);
  double t0 = MPI_Wtime();
  exchange.exchange(local.data());
  double once = MPI_Wtime() - t0;
  MPI_Allreduce(MPI_IN_PLACE, &once, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  const int repeats = std::max(10, std::min(100000, static_cast<int>(0.2 / std::max(once, 1e-7))));
  MPI_Barrier(MPI_COMM_WORLD);
  t0 = MPI_Wtime();
  for (int k = 0; k < repeats; ++k) exchange.exchange(local.data());
  double mean = (MPI_Wtime() - t0) / repeats;
  MPI_Allreduce(MPI_IN_PLACE, &mean, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  Figures f;
  f.haloNodes = exchange.plan().haloNodes();
  f.bytes = exchange.bytesSent();
  f.messages = exchange.messagesSent();
  f.seconds = mean;
  return f;
}

}  // namespace

int main(int argc, char** argv) {
  const bench::MpiRun mpi = bench::startMpi(argc, argv, 1, 16);
  const int rank = mpi.rank, ranks = mpi.ranks;
  const std::vector<long>& arguments = mpi.arguments;
  const Index reach = arguments.empty() ? 1 : arguments[0];
  std::vector<Index> sizes(arguments.size() > 1 ? arguments.begin() + 1 : arguments.end(), arguments.end());
  if (sizes.empty()) sizes = {8, 32, 64, 128, 200};
  if (rank == 0) {
    std::printf("Halo exchange, %d ranks, reach %ld, 3 values per node (rank 0's halo; time: slowest rank)\n", ranks,
                static_cast<long>(reach));
    std::printf("| nodes | per rank | halo nodes | messages | bytes sent | exchange [us] | bandwidth [GB/s] |\n");
    std::printf("|---|---|---|---|---|---|---|\n");
  }
  for (Index n : sizes) {
    const Figures f = measure(n, reach, rank, ranks);
    if (rank == 0)
      std::printf("| %ld^3 | %.3g | %ld | %d | %zu | %.1f | %.2f |\n", static_cast<long>(n),
                  static_cast<double>(n * n * n) / ranks, static_cast<long>(f.haloNodes), f.messages, f.bytes,
                  f.seconds * 1e6, f.seconds > 0 ? static_cast<double>(f.bytes) / f.seconds / 1e9 : 0.0);
  }
  MPI_Finalize();
  return 0;
}
