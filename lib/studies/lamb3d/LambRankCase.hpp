#pragma once
// A very weak SPH case of the Lamb study split over the ranks of mpirun (issue 22), built only with
// MPI. Every rank sets up the whole problem as a serial run does (the particles, the lattice
// stencils, the stable step: a set-up of O(N) per rank, docs/scaling.md); then each steps its share
// of the lattice system (LatticeShare), the probes travel to every rank (RankProbes), the energy
// ledger sums over the ranks in the serial order, and VTK frames are written as one piece per rank
// (ParallelVtkFrameWriter), the smoothing filter applies its stencils to the rank's share
// (RankStencilProduct) and deconvolved probes gather their rows' neighbours (RankProbes). The
// state, the probes and the ledger are the serial run's bit for bit,
// so the case's errors are too. Rank 0 scores the probes and writes the files; the others write
// their frame pieces only.

#include "studies/lamb3d/LambCase.hpp"

#include "core/Stopwatch.hpp"
#include "methods/very_weak_sph/VeryWeakSphProblem.hpp"
#include "observers/LinearEnergyLedger.hpp"
#include "particles/ParticleSet.hpp"

#include <string>

namespace mfwave::lamb3d {

// Why `problem` cannot be stepped on the ranks (a serial-only feature it uses), or empty when it
// can: the lattice storage (its smoothing filter too) with loads as nonzero entries, central
// differences, no prescribed faces. Its checkpoints are written per rank
// (decomposition/mpi/RankCheckpointStore, which the driver installs).
template <int D>
std::string whyNotOnRanks(VeryWeakSphProblem<D>& problem, const Scene& scene);

// Steps the case on the ranks of MPI_COMM_WORLD from the set-up a serial case made (`result` holds
// its record so far) and returns the result; on ranks other than 0 the probes are not scored.
template <int D>
CaseResult runOnRanks(const StudySettings& study, const CaseSettings& settings, const std::string& folder,
                      bool progress, const ParticleSet<D>& particles, VeryWeakSphProblem<D>& problem, Real dt,
                      const LinearEnergyLedgerOptions& ledgerOptions, CaseResult result,
                      const Stopwatch& setupClock);

}  // namespace mfwave::lamb3d
