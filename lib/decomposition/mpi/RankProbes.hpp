#pragma once
// Probes of a run split over ranks (issue 22): each probe's particle lives on one rank, which reads
// its value from the owned state; every rank gets every probe's series, so each rank can score
// them and rank 0 writes them once. The values travel by one MPI_Allreduce (sum) per sample, where
// the other ranks add -0.0: x + (-0.0) is x for every x, +0 and -0 included, so the series are the
// serial ones bit for bit.

#include "observers/ReportedProbes.hpp"

#include <mpi.h>

#include <vector>

namespace mfwave {

class RankProbes : public ReportedProbes {
 public:
  // `localParticle[i]`: probe i's particle in this rank's state (dof = particle * components +
  // component), or -1 when another rank owns it. Collective: throws Error on every rank unless each
  // probe is owned by exactly one rank.
  RankProbes(std::vector<Probe> probes, std::vector<Index> localParticle, int components, MPI_Comm communicator);

  void observe(const StateView& s) override;

 private:
  std::vector<Index> local_;
  int components_;
  MPI_Comm communicator_;
  std::vector<Real> values_;
};

}  // namespace mfwave
