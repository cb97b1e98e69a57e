// Strong and weak scaling of a distributed run (lib/decomposition/mpi/DistributedLatticeSystem),
// run under mpirun on 1 and 2 ranks:
//
//   mpirun -np 2 build/release/benchmarks/mpi/distributed_step_cost [side] [steps]
//
// (as root with OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 in the environment).
// The operator is the very weak SPH's Galerkin variant on its lattice stencils (the lamb3d method)
// on a free block, lambda = mu = rho = 1: strong scaling on side^3 particles, weak scaling on
// side x side x (side ranks), side^3 per rank. Central difference, one thread per rank; after two
// warm-up steps, `steps` steps are timed (the slowest rank). On one rank the serial
// LatticeSecondOrderSystem runs the same steps too, for the cost of the distributed system itself.
// Then the load balance near absorbing faces: a side^3 block with dashpots on five faces (lamb3d's:
// all but +z) cut across z only, so one rank holds the -z dashpots and the other the free face,
// balanced once with equal row costs and once with latticeRowCosts (what LatticeShare uses); the
// decomposition's predicted imbalance is printed beside the measured step.
// Rank 0 prints Markdown tables (docs/scaling.md shows them).
#include "../GalerkinBlock.hpp"
#include "MpiArguments.hpp"
#include "decomposition/mpi/DistributedLatticeSystem.hpp"
#include "decomposition/mpi/LatticeShare.hpp"
#include "particles/BoxFace.hpp"
#include "integrators/CentralDifference.hpp"
#include "methods/very_weak_sph/VeryWeakSphProblem.hpp"
#include "particles/Lattice.hpp"

#include <mpi.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

using namespace mfwave;

namespace {

constexpr Real kSpacing = 0.05;

std::unique_ptr<VeryWeakSphProblem<3>> freeBlock(const std::array<Index, 3>& nodes) {
  const VeryWeakSphProblemSettings<3> s = bench::galerkinBlock(nodes, kSpacing, 0);  // free: no dashpots
  return std::make_unique<VeryWeakSphProblem<3>>(makeLattice<3>(s.lower, s.upper, kSpacing), s);
}

// Seconds per step of `steps` central-difference steps (after two), the slowest rank's.
double timeSteps(SecondOrderSystem& system, const Vector& u0, int steps) {
  CentralDifference run;
  run.initialise(system, 0, u0, Vector::Zero(u0.size()), 0.2 * kSpacing);
  run.step();
  run.step();
  MPI_Barrier(MPI_COMM_WORLD);
  const double start = MPI_Wtime();
  for (int n = 0; n < steps; ++n) run.step();
  double seconds = (MPI_Wtime() - start) / steps;
  MPI_Allreduce(MPI_IN_PLACE, &seconds, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  return seconds;
}

void row(const char* mode, const std::array<Index, 3>& nodes, int steps, int rank, int ranks) {
  const std::unique_ptr<VeryWeakSphProblem<3>> problem = freeBlock(nodes);  // every rank builds the whole set-up
  const LatticeSecondOrderSystem<3>& serial = *problem->latticeSystem();
  const Index total = serial.types().nodeCount();
  Vector u0(3 * total);
  for (Index i = 0; i < u0.size(); ++i) u0[i] = 1e-3 * std::sin(0.37 * static_cast<Real>(i));
  const BlockDecomposition<3> decomposition(serial.types(), ranks, {}, {false, true, true});
  DistributedLatticeSystem<3> distributed(serial, decomposition, rank, MPI_COMM_WORLD);
  const double seconds = timeSteps(distributed, distributed.restrict(u0), steps);
  std::string serialCost = "";
  if (ranks == 1) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f", timeSteps(problem->system(), u0, steps) * 1e3);
    serialCost = text;
  }
  if (rank == 0) {
    const double perRank = static_cast<double>(total) / ranks;
    std::printf("| %s | %ld x %ld x %ld | %d | %.3g | %zu | %d | %.2f | %s | %.3g | %.3g |\n", mode,
                static_cast<long>(nodes[0]), static_cast<long>(nodes[1]), static_cast<long>(nodes[2]), ranks, perRank,
                distributed.exchange().bytesSent(), distributed.exchange().messagesSent(),
                seconds * 1e3, serialCost.empty() ? "-" : serialCost.c_str(), static_cast<double>(total) / seconds,
                perRank / seconds);
  }
}

// The absorbing block cut across z, its blocks balanced by `costs` (empty: equal).
void absorbingRow(const char* balance, bool rowCosts, Index n, int steps, int rank, int ranks) {
  const std::uint8_t faces = static_cast<std::uint8_t>(allFaces(3) & ~faceBit(BoxFace::PlusZ));
  const VeryWeakSphProblemSettings<3> s = bench::galerkinBlock({n, n, n}, kSpacing, faces);
  const VeryWeakSphProblem<3> problem(s);  // from the lattice's description
  const LatticeSecondOrderSystem<3>& serial = *problem.latticeSystem();
  const Index total = serial.types().nodeCount();
  Vector u0(3 * total);
  for (Index i = 0; i < u0.size(); ++i) u0[i] = 1e-3 * std::sin(0.37 * static_cast<Real>(i));
  const std::vector<Real> costs = rowCosts ? latticeRowCosts<3>(serial) : std::vector<Real>{};
  const BlockDecomposition<3> decomposition(serial.types(), ranks, costs, {false, false, true});
  DistributedLatticeSystem<3> distributed(serial, decomposition, rank, MPI_COMM_WORLD);
  const double seconds = timeSteps(distributed, distributed.restrict(u0), steps);
  Index owned = distributed.owned().count();
  std::vector<long> counts(static_cast<std::size_t>(ranks));
  long mine = static_cast<long>(owned);
  MPI_Gather(&mine, 1, MPI_LONG, counts.data(), 1, MPI_LONG, 0, MPI_COMM_WORLD);
  if (rank == 0) {
    std::string split;
    for (long c : counts) split += (split.empty() ? "" : " / ") + std::to_string(c);
    std::printf("| %s | %ld^3 | %d | %s | %.3f | %.2f |\n", balance, static_cast<long>(n), ranks, split.c_str(),
                rowCosts ? decomposition.imbalance() : BlockDecomposition<3>(serial.types(), ranks, latticeRowCosts<3>(serial),
                                                                             {false, false, true}).imbalance(),
                seconds * 1e3);
  }
}

}  // namespace

int main(int argc, char** argv) {
  const bench::MpiRun mpi = bench::startMpi(argc, argv, 4, 2);
  const int rank = mpi.rank, ranks = mpi.ranks;
  const long side = mpi.arguments.size() > 0 ? mpi.arguments[0] : 64;
  const long steps = mpi.arguments.size() > 1 ? mpi.arguments[1] : 20;
  if (rank == 0) {
    std::printf("Distributed central difference, Galerkin very weak SPH, free block, %d ranks, one thread each\n", ranks);
    std::printf("| scaling | lattice | ranks | particles per rank | halo bytes per step (rank 0) | messages | step [ms] | serial system [ms] | particle-steps/s | per rank |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
  }
  const Index n = side;
  row("strong", {n, n, n}, static_cast<int>(steps), rank, ranks);
  row("weak", {n, n, n * ranks}, static_cast<int>(steps), rank, ranks);
  if (rank == 0) {
    std::printf("\nDashpots on five faces (lamb3d's), blocks cut across z; imbalance: max / mean row cost by latticeRowCosts\n");
    std::printf("| balanced by | lattice | ranks | nodes per rank | predicted imbalance | step [ms] |\n");
    std::printf("|---|---|---|---|---|---|\n");
  }
  absorbingRow("equal row costs", false, n, static_cast<int>(steps), rank, ranks);
  absorbingRow("latticeRowCosts", true, n, static_cast<int>(steps), rank, ranks);
  MPI_Finalize();
  return 0;
}
