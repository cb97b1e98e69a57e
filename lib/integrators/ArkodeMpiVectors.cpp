// The MPI half of the ARKODE adapter (see ArkodeVectorHook.hpp for why it is a library of its own).
#include "integrators/ArkodeMpiVectors.hpp"

#include "integrators/ArkodeVectorHook.hpp"

#include <mpi.h>
#include <nvector/nvector_parallel.h>

namespace mfwave {
namespace {

N_Vector makeParallelVector(const void* communicator, sunindextype localLength, sunindextype globalLength,
                            sunrealtype* data, SUNContext context) {
  // N_VMake_Parallel checks that the local lengths sum to globalLength (an all-reduce) and returns
  // null when they do not; the data stay the caller's.
  return N_VMake_Parallel(*static_cast<const MPI_Comm*>(communicator), localLength, globalLength, data, context);
}

}  // namespace

void enableArkodeMpiVectors() { setArkodeParallelVectorMaker(&makeParallelVector); }

}  // namespace mfwave
