#include "decomposition/mpi/MpiSession.hpp"

#include <cstdlib>

namespace mfwave {

namespace {

bool launchedByMpirun() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
    if (std::getenv(name) != nullptr) return true;
  return false;
}

}  // namespace

MpiSession::MpiSession(int& argc, char**& argv) {
  if (active() || !launchedByMpirun()) return;
  MPI_Init(&argc, &argv);
  started_ = true;
}

MpiSession::~MpiSession() {
  if (started_ && active()) MPI_Finalize();
}

bool MpiSession::active() {
  int initialised = 0, finalised = 0;
  MPI_Initialized(&initialised);
  MPI_Finalized(&finalised);
  return initialised != 0 && finalised == 0;
}

int MpiSession::rank() {
  if (!active()) return 0;
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  return rank;
}

int MpiSession::size() {
  if (!active()) return 1;
  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  return size;
}

void MpiSession::abortOthers(int code) {
  if (size() > 1) MPI_Abort(MPI_COMM_WORLD, code);
}

}  // namespace mfwave
