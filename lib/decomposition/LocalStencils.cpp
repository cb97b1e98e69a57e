#include "decomposition/LocalStencils.hpp"

#include "core/Error.hpp"
#include "lattice/StencilRun.hpp"

#include <algorithm>
#include <string>

namespace mfwave {

template <int D, int C>
LocalStencils<D, C>::LocalStencils(const LatticeStencils<D, C>& stencils, const Box<D>& owned, const Box<D>& local)
    : stencils_(&stencils), owned_(owned), local_(local) {
  const LatticeRowTypes<D>& types = stencils.types();
  Box<D> lattice;
  lattice.hi = types.nodes();
  if (owned.empty() || intersection(owned, lattice) != owned)
    throw InputError("lattice", "the owned box is empty or reaches outside the lattice");
  // Every row of an owned node reads inside the local box. Per type, the owned nodes of that type
  // span a box (per axis, the owned range of the nodes with the type's compact index), and the
  // type's entries must stay inside `local` from both of its corners.
  Box<D> compact;
  compact.hi = types.compactNodes();
  compact.forEachNode([&](const std::array<Index, D>& c) {
    Box<D> ofType;
    for (int a = 0; a < D; ++a) {
      const auto s = static_cast<std::size_t>(a);
      const std::array<Index, 2> run = types.nodesOfCompactIndex(a, c[s]);
      ofType.lo[s] = std::max(run[0], owned.lo[s]);
      ofType.hi[s] = std::min(run[1], owned.hi[s]);
    }
    if (ofType.empty()) return;
    const Index type = compact.localIndex(c);
    for (Index e = stencils.begin(type); e < stencils.end(type); ++e)
      for (int a = 0; a < D; ++a) {
        const auto s = static_cast<std::size_t>(a);
        const Index o = stencils.offset(e)[s];
        if (ofType.lo[s] + o < local.lo[s] || ofType.hi[s] - 1 + o >= local.hi[s])
          throw InputError("halo", "a row of type " + std::to_string(type) + " reads " + std::to_string(o) +
                                       " nodes along axis " + std::to_string(a) +
                                       ", beyond the local box: the halo is shallower than the stencils' reach");
      }
  });
  // The halo lies where the local box passes the owned one; a row of a node within the reach of
  // such a side reads it.
  const std::array<Index, D> reach = stencilReach(stencils);
  inner_ = owned;
  for (int a = 0; a < D; ++a) {
    const auto s = static_cast<std::size_t>(a);
    if (local.lo[s] < owned.lo[s]) inner_.lo[s] = owned.lo[s] + reach[s];
    if (local.hi[s] > owned.hi[s]) inner_.hi[s] = owned.hi[s] - reach[s];
  }
  xReadsHalo_ = inner_.lo[0] != owned.lo[0] || inner_.hi[0] != owned.hi[0];
  std::array<Index, D> storage{};
  for (int a = 0; a < D; ++a) storage[static_cast<std::size_t>(a)] = local.extent(a);
  flat_ = stencils.flatOffsets(storage);
  table_ = freshStencilNumbers(static_cast<std::uint64_t>(std::max<Index>(stencils.typeCount(), 1)));
}

template <int D, int C>
void LocalStencils<D, C>::multiply(const Real* x, Real* y, const std::vector<char>* direct, OwnedLines lines) const {
  forEachProduct(
      x,
      [y](Index k, Index, const Real* product, Index stride) {
        for (int c = 0; c < C; ++c) y[C * k + c] = product[c * stride];
      },
      [direct](Index type) { return direct && (*direct)[static_cast<std::size_t>(type)]; }, lines);
}

template class LocalStencils<1>;
template class LocalStencils<2>;
template class LocalStencils<3>;
template class LocalStencils<2, 1>;
template class LocalStencils<3, 1>;

}  // namespace mfwave
