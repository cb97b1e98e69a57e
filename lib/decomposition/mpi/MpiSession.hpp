#pragma once
// MPI for a driver that also runs without mpirun (issue 22): MPI is initialised only when the
// process was started by a launcher (mpirun sets OMPI_COMM_WORLD_SIZE; PMI and PMIx launchers set
// PMI_SIZE, PMIX_RANK), so a plain run never starts MPI, and finalised when the session ends. A
// failure on one rank must not leave the others waiting in a halo exchange: abortOthers() ends the
// whole job with the failing rank's exit code.

#include <mpi.h>

namespace mfwave {

class MpiSession {
 public:
  MpiSession(int& argc, char**& argv);
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

  // True when MPI was started (by this session or before it) and not yet finalised.
  static bool active();
  // This process's rank and the rank count in MPI_COMM_WORLD (0 and 1 without MPI).
  static int rank();
  static int size();
  // With more than one rank: MPI_Abort(MPI_COMM_WORLD, code), which does not return. Otherwise
  // returns, so a serial driver goes on to exit with `code` normally.
  static void abortOthers(int code);

 private:
  bool started_ = false;
};

}  // namespace mfwave
