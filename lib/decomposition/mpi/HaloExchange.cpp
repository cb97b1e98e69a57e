#include "decomposition/mpi/HaloExchange.hpp"

#include "core/Error.hpp"

#include <algorithm>
#include <string>
#include <utility>

namespace mfwave {

namespace {

// Calls line(first, length) for each lattice line of `box` (along x), with the local offset of its
// first node in the box `local` and its node count.
template <int D, class Line>
void forEachLine(const Box<D>& box, const Box<D>& local, Line&& line) {
  Box<D> starts = box;
  starts.hi[0] = box.lo[0] + 1;
  const Index length = box.extent(0);
  starts.forEachNode([&](const std::array<Index, D>& node) { line(local.localIndex(node), length); });
}

void check(int code, const char* call) {
  if (code != MPI_SUCCESS) throw Error(std::string("halo exchange: ") + call + " failed with MPI error " + std::to_string(code));
}

}  // namespace

template <int D>
HaloExchange<D>::HaloExchange(HaloPlan<D> plan, int components, MPI_Comm communicator, int tag)
    : plan_(std::move(plan)), components_(components), communicator_(communicator), tag_(tag) {
  if (components < 1) throw InputError("components", "a node needs at least one value, got " + std::to_string(components));
  for (const auto& message : plan_.sends())
    sendBuffers_.emplace_back(static_cast<std::size_t>(message.nodes.count() * components_));
  for (const auto& message : plan_.receives())
    receiveBuffers_.emplace_back(static_cast<std::size_t>(message.nodes.count() * components_));
  requests_.resize(sendBuffers_.size() + receiveBuffers_.size(), MPI_REQUEST_NULL);
}

template <int D>
HaloExchange<D>::~HaloExchange() {
  // An exchange abandoned by an exception: complete it rather than leave MPI writing into freed
  // buffers.
  if (inFlight_) MPI_Waitall(static_cast<int>(requests_.size()), requests_.data(), MPI_STATUSES_IGNORE);
}

template <int D>
void HaloExchange<D>::start(const Real* local) {
  if (inFlight_) throw Error("halo exchange: start() while an exchange is in flight");
  const auto C = static_cast<Index>(components_);
  std::size_t request = 0;
  for (std::size_t k = 0; k < plan_.receives().size(); ++k)
    check(MPI_Irecv(receiveBuffers_[k].data(), static_cast<int>(receiveBuffers_[k].size()), MPI_DOUBLE,
                    plan_.receives()[k].rank, tag_, communicator_, &requests_[request++]),
          "MPI_Irecv");
  for (std::size_t k = 0; k < plan_.sends().size(); ++k) {
    Real* out = sendBuffers_[k].data();
    forEachLine(plan_.sends()[k].nodes, plan_.local(), [&](Index first, Index length) {
      out = std::copy(local + first * C, local + (first + length) * C, out);
    });
    check(MPI_Isend(sendBuffers_[k].data(), static_cast<int>(sendBuffers_[k].size()), MPI_DOUBLE, plan_.sends()[k].rank,
                    tag_, communicator_, &requests_[request++]),
          "MPI_Isend");
  }
  inFlight_ = true;
}

template <int D>
void HaloExchange<D>::finish(Real* local) {
  if (!inFlight_) throw Error("halo exchange: finish() without start()");
  inFlight_ = false;
  check(MPI_Waitall(static_cast<int>(requests_.size()), requests_.data(), MPI_STATUSES_IGNORE), "MPI_Waitall");
  const auto C = static_cast<Index>(components_);
  for (std::size_t k = 0; k < plan_.receives().size(); ++k) {
    const Real* in = receiveBuffers_[k].data();
    forEachLine(plan_.receives()[k].nodes, plan_.local(), [&](Index first, Index length) {
      std::copy(in, in + length * C, local + first * C);
      in += length * C;
    });
  }
}

template class HaloExchange<1>;
template class HaloExchange<2>;
template class HaloExchange<3>;

}  // namespace mfwave
