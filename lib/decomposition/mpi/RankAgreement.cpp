#include "decomposition/mpi/RankAgreement.hpp"

#include "core/Error.hpp"

#include <string>

namespace mfwave {

TimeLoop::Agreement maximumOverRanks(MPI_Comm communicator) {
  return [communicator](int* values, int count) {
    const int code = MPI_Allreduce(MPI_IN_PLACE, values, count, MPI_INT, MPI_MAX, communicator);
    if (code != MPI_SUCCESS) throw Error("the ranks' step agreement: MPI_Allreduce failed with MPI error " + std::to_string(code));
  };
}

}  // namespace mfwave
