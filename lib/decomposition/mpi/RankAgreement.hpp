#pragma once
// The agreement of the ranks' time loops (issue 22): each value replaced by its maximum over the
// communicator, once per step (TimeLoop::agreeAcrossRanks). Under mpirun a signal reaches the
// ranks at different steps (or only some of them), and their wall clocks fire at different steps;
// agreeing on both at every step boundary keeps every rank stepping, stopping and checkpointing
// together. It costs one all-reduce of two integers per step: microseconds on one machine, against
// the milliseconds of a step of a block worth splitting.

#include "observers/TimeLoop.hpp"

#include <mpi.h>

namespace mfwave {

// Every rank of `communicator` must install it on the same loops. `communicator` must outlive the loop.
TimeLoop::Agreement maximumOverRanks(MPI_Comm communicator);

}  // namespace mfwave
