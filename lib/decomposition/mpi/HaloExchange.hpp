#pragma once
// The halo exchange of one rank over MPI (issue 22): with the HaloPlan's messages, start() packs
// the nodes each neighbour needs and posts non-blocking sends and receives, so the caller can work
// on the rows that need no halo meanwhile, and finish() waits and unpacks the received nodes into
// the halo. Data live in the rank's local box, x fastest, `components` values per node
// (HaloPlan.hpp). A message is its box's lattice lines, each a contiguous run of the local array.
//
// One exchange is in flight at a time per object; objects on the same communicator keep apart by
// their tags.

#include "core/Types.hpp"
#include "decomposition/HaloPlan.hpp"

#include <mpi.h>

#include <cstddef>
#include <vector>

namespace mfwave {

template <int D>
class HaloExchange {
 public:
  // Throws InputError("components") for components < 1.
  HaloExchange(HaloPlan<D> plan, int components, MPI_Comm communicator, int tag = 0);
  HaloExchange(const HaloExchange&) = delete;
  HaloExchange& operator=(const HaloExchange&) = delete;
  ~HaloExchange();

  const HaloPlan<D>& plan() const { return plan_; }
  // Values in the local box: local().count() * components.
  Index localSize() const { return plan_.local().count() * components_; }

  void start(const Real* local);
  void finish(Real* local);
  void exchange(Real* local) {
    start(local);
    finish(local);
  }

  // Per exchange: the messages this rank sends and their bytes.
  int messagesSent() const { return static_cast<int>(plan_.sends().size()); }
  std::size_t bytesSent() const { return static_cast<std::size_t>(plan_.sentNodes() * components_) * sizeof(Real); }

 private:
  HaloPlan<D> plan_;
  int components_;
  MPI_Comm communicator_;
  int tag_;
  std::vector<std::vector<Real>> sendBuffers_, receiveBuffers_;
  std::vector<MPI_Request> requests_;
  bool inFlight_ = false;
};

extern template class HaloExchange<1>;
extern template class HaloExchange<2>;
extern template class HaloExchange<3>;

}  // namespace mfwave
