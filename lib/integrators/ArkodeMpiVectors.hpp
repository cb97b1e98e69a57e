#pragma once
// SUNDIALS' MPI vectors (N_Vector Parallel) for the ARKODE integrators, in MPI builds only
// (library mfwave::integrators_mpi, built with MFWAVE_MPI). After this call, ArkodeExplicit (and so
// ArkodeFirstOrder and ArkodeSecondOrder) runs a system that reports a VectorDistribution on the
// parallel N_Vector over its communicator, and creates its SUNContext with that communicator:
// every rank then takes the same adaptive steps. Without it a distributed system is refused.
// Idempotent; DistributedLatticeSystem calls it from its constructor. Needs neither MPI nor
// SUNDIALS headers.

namespace mfwave {

void enableArkodeMpiVectors();

}  // namespace mfwave
