#pragma once
// The start of the MPI benchmark programs: MPI initialised, this rank and the rank count, and the
// command line's integers, each at least `smallest`, at most `most` of them. On a bad command line
// rank 0 says what is wrong, and every rank finalises MPI and exits 2.

#include <mpi.h>

#include <cstdio>
#include <cstdlib>
#include <vector>

namespace mfwave::bench {

struct MpiRun {
  int rank = 0;
  int ranks = 1;
  std::vector<long> arguments;
};

inline MpiRun startMpi(int& argc, char**& argv, long smallest, std::size_t most) {
  MPI_Init(&argc, &argv);
  MpiRun run;
  MPI_Comm_rank(MPI_COMM_WORLD, &run.rank);
  MPI_Comm_size(MPI_COMM_WORLD, &run.ranks);
  bool good = static_cast<std::size_t>(argc - 1) <= most;
  if (!good && run.rank == 0) std::fprintf(stderr, "%s: at most %zu arguments\n", argv[0], most);
  for (int a = 1; good && a < argc; ++a) {
    char* end = nullptr;
    const long value = std::strtol(argv[a], &end, 10);
    good = end != argv[a] && *end == '\0' && value >= smallest;
    if (!good && run.rank == 0)
      std::fprintf(stderr, "%s: argument %d (\"%s\") must be an integer >= %ld\n", argv[0], a, argv[a], smallest);
    run.arguments.push_back(value);
  }
  if (!good) {
    MPI_Finalize();
    std::exit(2);
  }
  return run;
}

}  // namespace mfwave::bench
