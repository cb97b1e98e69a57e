#pragma once
// What one rank sends and receives so that its stencil rows can be applied (issue 22): the rank's
// block, grown by the stencil's reach (clipped to the lattice), is the box of nodes it holds; the
// nodes of that box it does not own are its halo, owned by other ranks. Each message is a box:
//   send to q:       my block  ∩  q's block grown by the reach,
//   receive from q:  q's block ∩  my block grown by the reach,
// so what q sends me is exactly what I receive from q, and each rank computes both without
// talking to the others. A rank's data live in its local box, x fastest (Box::localIndex), with
// `components` values per node; messages are packed in the order of their box's nodes.

#include "decomposition/BlockDecomposition.hpp"
#include "lattice/Box.hpp"

#include <array>
#include <vector>

namespace mfwave {

template <int D>
struct HaloMessage {
  int rank = 0;  // the other rank
  Box<D> nodes;  // in lattice coordinates
};

template <int D>
class HaloPlan {
 public:
  // Throws InputError("reach") for a negative reach, InputError("rank") for a rank outside the
  // decomposition.
  HaloPlan(const BlockDecomposition<D>& decomposition, int rank, const std::array<Index, D>& reach);

  int rank() const { return rank_; }
  const Box<D>& owned() const { return owned_; }
  const Box<D>& local() const { return local_; }
  // Messages to and from the other ranks, in increasing rank order; empty boxes are left out.
  const std::vector<HaloMessage<D>>& sends() const { return sends_; }
  const std::vector<HaloMessage<D>>& receives() const { return receives_; }
  Index haloNodes() const { return local_.count() - owned_.count(); }
  Index sentNodes() const;

 private:
  int rank_ = 0;
  Box<D> owned_, local_;
  std::vector<HaloMessage<D>> sends_, receives_;
};

extern template class HaloPlan<1>;
extern template class HaloPlan<2>;
extern template class HaloPlan<3>;

}  // namespace mfwave
