#pragma once
// For the ARKODE adapter's own files only (ArkodeExplicit.cpp, ArkodeMpiVectors.cpp): the hook
// through which an MPI build hands ArkodeExplicit SUNDIALS' MPI vectors (issue 22).
//
// Why a hook rather than N_VMake_Parallel in ArkodeExplicit.cpp behind an #ifdef: the integrators
// library must build and link without MPI, and with MFWAVE_MPI on it still should not, because
// every driver links it and a study run on one process should not load Open MPI. The MPI half
// (ArkodeMpiVectors.cpp) is its own library, mfwave::integrators_mpi, built with MFWAVE_MPI only and
// linked by what builds distributed systems (lib/decomposition/mpi), which installs the maker
// before it hands a distributed system to an integrator.

#include <sundials/sundials_nvector.h>
#include <sundials/sundials_types.h>

namespace mfwave {

// An N_Vector of local length `localLength` over `data` (not owned: N_VDestroy leaves it), whose
// global operations reduce over the communicator. `communicator` is
// VectorDistribution::communicator (a pointer to an MPI_Comm).
using ArkodeParallelVectorMaker = N_Vector (*)(const void* communicator, sunindextype localLength,
                                               sunindextype globalLength, sunrealtype* data, SUNContext context);

// Installs the maker (idempotent; one per process).
void setArkodeParallelVectorMaker(ArkodeParallelVectorMaker maker);

}  // namespace mfwave
