#pragma once
// How a system's vectors are laid out over processes, told to integrators without MPI (issue 22).
// A system that holds one rank's share of the unknowns (lib/decomposition/mpi) reports the
// communicator and the global length; an integrator whose vectors take part in global operations
// (ARKODE's WRMS norms, which choose adaptive steps) then builds distributed vectors, so every rank
// sees the same norms and takes the same steps. Integrators never see ranks beyond this: they pass
// the handle on to the one adapter that talks to SUNDIALS (integrators/ArkodeExplicit.cpp).
//
// The communicator is opaque (a pointer to the system's MPI_Comm) so that lib/systems and
// lib/integrators build and link without MPI; only the code that makes MPI vectors casts it back.
//
// A system may also fix the order of the sums behind those norms (orderedSumOfSquares): SUNDIALS'
// own sums run over each rank's entries and then over the ranks, so their last bits, and with them
// an adaptive run's steps, change with the rank count. The lattice systems sum in lattice order
// (lines along x, then the lines in order), serially and on any number of ranks alike, so an
// adaptive run takes the same steps and keeps the same bits on every rank count.

#include "core/Types.hpp"

#include <functional>

namespace mfwave {

struct VectorDistribution {
  // Points to an MPI_Comm owned by the system (it lives as long as the system).
  const void* communicator = nullptr;
  // The sum of every rank's size(): the length of the global vector.
  Index globalSize = 0;
  // sum_i z_i^2 over the whole vector, given this rank's `count` values of z (collective: every
  // rank calls it), in an order the system fixes; empty: SUNDIALS' own sums. A serial system may
  // give this alone, with a null communicator.
  std::function<Real(const Real* z, Index count)> orderedSumOfSquares;
};

}  // namespace mfwave
