#pragma once
// Probes of a run split over ranks (issue 22): each probe's particle lives on one rank, which reads
// its value from the owned state; every rank gets every probe's series, so each rank can score
// them and rank 0 writes them once. The values travel by one MPI_Allreduce (sum) per sample, where
// the other ranks add -0.0: x + (-0.0) is x for every x, +0 and -0 included, so the series are the
// serial ones bit for bit.
//
// A reported value may be a weighted sum over the probe's neighbours (the published very weak
// SPH's deconvolution, Ding-Long-Wu eq. (35)): then the neighbours' values travel the same way and
// every rank adds the row in its serial order (deconvolveAt), so the reported series are bitwise
// the serial ones too.

#include "observers/ReportedProbes.hpp"

#include <Eigen/SparseCore>
#include <mpi.h>

#include <functional>
#include <vector>

namespace mfwave {

class RankProbes : public ReportedProbes {
 public:
  // A particle's place in this rank's state (dof = place * components + component), -1 when
  // another rank owns it.
  using LocalParticle = std::function<Index(Index particle)>;
  // Row i for probe i (global columns), as deconvolutionRows of the probes' particles gives them.
  using Rows = Eigen::SparseMatrix<Real, Eigen::RowMajor, int>;

  // `rows` may be null (reported = raw) and must outlive the recorder. Collective: throws Error on
  // every rank unless each probe is owned by exactly one rank.
  RankProbes(std::vector<Probe> probes, const LocalParticle& localParticle, int components, MPI_Comm communicator,
             const Rows* rows = nullptr);

  void observe(const StateView& s) override;

 private:
  struct Read {
    Index local;     // in this rank's state, or -1
    int component;
    bool velocity;
  };
  std::vector<Read> reads_;        // the probes' own values, then each probe's row's columns in order
  std::vector<std::size_t> rowStart_;  // per probe: its row's first read (reads_.size() + 1 entries)
  std::vector<Real> weights_;      // per row read
  int components_;
  MPI_Comm communicator_;
  std::vector<Real> values_;
};

}  // namespace mfwave
