#pragma once
// A lattice operator's rows for the nodes one rank owns (issue 22): the stencils of the whole
// lattice (LatticeStencils), each row's type taken from the node's place in the whole lattice, the
// columns read from the rank's local box (its block and halo, HaloPlan.hpp), whose node offsets
// differ from the whole lattice's. Every node takes the path it takes in the serial product: the
// middle of its lattice line through stencilRun, the ends row by row, in the same order, so each
// owned row is bitwise the serial one, on any number of ranks and threads.

#include "core/Types.hpp"
#include "decomposition/Box.hpp"
#include "lattice/LatticeStencils.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace mfwave {

// The largest |offset| along each axis over the stencils' entries: the halo depth their rows read.
template <int D>
std::array<Index, D> stencilReach(const LatticeStencils<D>& stencils);

template <int D>
class LocalStencils {
 public:
  // `stencils` must outlive this object. Throws InputError("halo") when a row of `owned` reads a
  // node outside `local`, InputError("lattice") when `owned` is not inside the lattice.
  LocalStencils(const LatticeStencils<D>& stencils, const Box<D>& owned, const Box<D>& local);

  const Box<D>& owned() const { return owned_; }
  const Box<D>& local() const { return local_; }

  // y (D values per owned node, in the owned box's order) = the owned rows applied to x (D values
  // per node of the local box, in its order). OpenMP-parallel over lines along x. `direct`, when
  // given, marks the row types whose middle of line is computed row by row, as the serial
  // LatticeStencils::forEachProduct does for its `direct` types (the dashpot rows of a fused solve).
  void multiply(const Real* x, Real* y, const std::vector<char>* direct = nullptr) const;

 private:
  const LatticeStencils<D>* stencils_;
  Box<D> owned_, local_;
  std::vector<Index> flat_;  // per entry: the offset as a node-index difference in the local box
  std::uint64_t table_ = 0;  // stencil numbers of these offsets (freshStencilNumbers)
};

extern template class LocalStencils<1>;
extern template class LocalStencils<2>;
extern template class LocalStencils<3>;
extern template std::array<Index, 1> stencilReach<1>(const LatticeStencils<1>&);
extern template std::array<Index, 2> stencilReach<2>(const LatticeStencils<2>&);
extern template std::array<Index, 3> stencilReach<3>(const LatticeStencils<3>&);

}  // namespace mfwave
