#include "decomposition/HaloPlan.hpp"

#include "core/Error.hpp"

#include <string>

namespace mfwave {

template <int D>
HaloPlan<D>::HaloPlan(const BlockDecomposition<D>& decomposition, int rank, const std::array<Index, D>& reach)
    : rank_(rank) {
  if (rank < 0 || rank >= decomposition.ranks())
    throw InputError("rank", std::to_string(rank) + " is not one of the decomposition's " +
                                 std::to_string(decomposition.ranks()) + " ranks");
  for (Index r : reach)
    if (r < 0) throw InputError("reach", "a stencil's reach cannot be negative, got " + std::to_string(r));
  const auto& nodes = decomposition.nodes();
  owned_ = decomposition.block(rank);
  local_ = grown<D>(owned_, reach, nodes);
  for (int q = 0; q < decomposition.ranks(); ++q) {
    if (q == rank) continue;
    const Box<D> theirs = decomposition.block(q);
    const Box<D> send = intersection(owned_, grown<D>(theirs, reach, nodes));
    if (!send.empty()) sends_.push_back({q, send});
    const Box<D> receive = intersection(theirs, local_);
    if (!receive.empty()) receives_.push_back({q, receive});
  }
}

template <int D>
Index HaloPlan<D>::sentNodes() const {
  Index total = 0;
  for (const auto& message : sends_) total += message.nodes.count();
  return total;
}

template class HaloPlan<1>;
template class HaloPlan<2>;
template class HaloPlan<3>;

}  // namespace mfwave
