#include "decomposition/LocalStencils.hpp"

#include "core/Error.hpp"
#include "lattice/StencilRun.hpp"

#include <algorithm>
#include <string>

namespace mfwave {

template <int D>
std::array<Index, D> stencilReach(const LatticeStencils<D>& stencils) {
  std::array<Index, D> reach{};
  for (Index e = 0; e < stencils.entryCount(); ++e)
    for (std::size_t s = 0; s < static_cast<std::size_t>(D); ++s)
      reach[s] = std::max(reach[s], std::abs(stencils.offset(e)[s]));
  return reach;
}

template <int D>
LocalStencils<D>::LocalStencils(const LatticeStencils<D>& stencils, const Box<D>& owned, const Box<D>& local)
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
  std::array<Index, D> storage{};
  for (int a = 0; a < D; ++a) storage[static_cast<std::size_t>(a)] = local.extent(a);
  flat_ = stencils.flatOffsets(storage);
  table_ = freshStencilNumbers(static_cast<std::uint64_t>(std::max<Index>(stencils.typeCount(), 1)));
}

template <int D>
void LocalStencils<D>::multiply(const Real* x, Real* y, const std::vector<char>* direct) const {
  const LatticeStencils<D>& stencils = *stencils_;
  const LatticeRowTypes<D>& types = stencils.types();
  const Index nx = types.nodes()[0], depth = types.depth();
  const bool runs = types.compactNodes()[0] < nx;  // else every x position is its own type
  // The middle of the lattice's lines (one type) within the owned x range: the serial product's runs.
  const Index middleFirst = runs ? std::max(owned_.lo[0], depth) : owned_.hi[0];
  const Index middleLast = runs ? std::min(owned_.hi[0], nx - depth) : owned_.hi[0];
  const Index length = owned_.extent(0);
  Box<D> lineStarts = owned_;
  lineStarts.hi[0] = owned_.lo[0] + 1;
  const long lines = static_cast<long>(lineStarts.count());
  const std::uint64_t pass = nextStencilProduct();
#pragma omp parallel for schedule(static) if (lines > 16 && owned_.count() > 20000)
  for (long line = 0; line < lines; ++line) {
    // The line's first node, from its number in the owned box (x fastest, x fixed at lo).
    std::array<Index, D> g = owned_.lo;
    Index rest = line, base = 0, stride = types.compactNodes()[0];
    for (int a = 1; a < D; ++a) {
      const auto s = static_cast<std::size_t>(a);
      g[s] = owned_.lo[s] + rest % owned_.extent(a);
      rest /= owned_.extent(a);
      base += stride * types.compactIndex(a, g[s]);
      stride *= types.compactNodes()[s];
    }
    const Index in = local_.localIndex(g);   // the line's first node in x
    const Index out = owned_.localIndex(g);  // and in y
    auto single = [&](Index i) {
      stencils.rowProductAt(base + types.compactIndex(0, i), x + D * (in + i - owned_.lo[0]), flat_.data(),
                            y + D * (out + i - owned_.lo[0]));
    };
    for (Index i = owned_.lo[0]; i < std::min(middleFirst, owned_.hi[0]); ++i) single(i);
    if (middleLast > middleFirst && direct && (*direct)[static_cast<std::size_t>(base + depth)]) {
      for (Index i = middleFirst; i < middleLast; ++i) single(i);
    } else if (middleLast > middleFirst) {
      const Index type = base + depth, count = middleLast - middleFirst;
      // The type's stencil with the local box's offsets, under this table's own numbers.
      StencilView view = stencils.view(type);
      view.flat = flat_.data() + stencils.begin(type);
      view.table = table_ + static_cast<std::uint64_t>(type);
      thread_local StencilRunCache cache;
      thread_local std::vector<Real> run;
      if (run.size() < static_cast<std::size_t>(D * count)) run.resize(static_cast<std::size_t>(D * count));
      stencilRun<D>(view, x, in + middleFirst - owned_.lo[0], count, run.data(), cache, pass);
      for (Index l = 0; l < count; ++l)
        for (int c = 0; c < D; ++c) y[D * (out + middleFirst - owned_.lo[0] + l) + c] = run[static_cast<std::size_t>(c * count + l)];
    }
    for (Index i = std::max(middleLast, middleFirst); i < owned_.lo[0] + length; ++i) single(i);
  }
}

template class LocalStencils<1>;
template class LocalStencils<2>;
template class LocalStencils<3>;
template std::array<Index, 1> stencilReach<1>(const LatticeStencils<1>&);
template std::array<Index, 2> stencilReach<2>(const LatticeStencils<2>&);
template std::array<Index, 3> stencilReach<3>(const LatticeStencils<3>&);

}  // namespace mfwave
