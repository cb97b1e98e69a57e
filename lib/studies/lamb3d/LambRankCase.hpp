#pragma once
// A very weak SPH case of the Lamb study split over the ranks of mpirun (issue 22), built only with
// MPI. Each rank sets up only what it steps: the problem from the lattice's description (its
// stencils, loads and filter are a few kB whatever the lattice: VeryWeakSphProblem without
// particles), its share of the lattice system (LatticeShare), the stable step over the shares, the
// probes placed by lattice arithmetic and its own block's particles for the frames; no whole-lattice
// particle set or vector. Then it steps its share, the probes travel to every rank (RankProbes),
// the energy ledger sums over the ranks in the serial order, VTK frames are written as one piece per
// rank (ParallelVtkFrameWriter), the smoothing filter applies its stencils to the rank's share
// (RankStencilProduct) and deconvolved probes gather their rows' neighbours (RankProbes). The state,
// the probes and the ledger are the serial run's bit for bit, so the case's errors are too. Rank 0
// scores the probes and writes the files; the others write their frame pieces only.

#include "studies/lamb3d/LambCase.hpp"

#include "core/Stopwatch.hpp"
#include "methods/very_weak_sph/VeryWeakSphProblem.hpp"
#include "observers/LinearEnergyLedger.hpp"

#include <string>

namespace mfwave::lamb3d {

// Why a problem of `settings` cannot be stepped on the ranks (a serial-only feature it uses), or
// empty when it can: the lattice storage, an explicit integrator, no prescribed faces beside a
// kernel variant's dashpots (which may couple particles). Its
// checkpoints are written per rank (decomposition/mpi/RankCheckpointStore, which the driver
// installs).
template <int D>
std::string whyNotOnRanks(const VeryWeakSphProblemSettings<D>& settings, const Scene& scene);

// Sets up and steps the case on the ranks of MPI_COMM_WORLD (`result` holds its record so far,
// `setupClock` started with it) and returns the result; on ranks other than 0 the probes are not
// scored.
template <int D>
CaseResult runOnRanks(const StudySettings& study, const CaseSettings& settings, const std::string& folder,
                      bool progress, const VeryWeakSphProblemSettings<D>& problemSettings,
                      const LinearEnergyLedgerOptions& ledgerOptions, CaseResult result, const Stopwatch& setupClock);

}  // namespace mfwave::lamb3d
