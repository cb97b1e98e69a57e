#pragma once
// A lattice operator's rows for the nodes one rank owns (issue 22): the stencils of the whole
// lattice (LatticeStencils), each row's type taken from the node's place in the whole lattice, the
// columns read from the rank's local box (its block and halo, HaloPlan.hpp), whose node offsets
// differ from the whole lattice's. Every node takes the path it takes in the serial product: the
// middle of its lattice line through stencilRun, the ends row by row, in the same order, so each
// owned row is bitwise the serial one, on any number of ranks and threads.

#include "core/Types.hpp"
#include "lattice/Box.hpp"
#include "lattice/StencilReach.hpp"
#include "lattice/LatticeStencils.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace mfwave {

// C components per node, as the stencils' (LatticeStencils<D, C>).
// Which owned lines a product visits: all, those whose rows read owned nodes only (computed while
// the halo is in flight), or the others (once it has arrived).
enum class OwnedLines { All, WithoutHalo, WithHalo };

template <int D, int C = D>
class LocalStencils {
 public:
  // `stencils` must outlive this object. Throws InputError("halo") when a row of `owned` reads a
  // node outside `local`, InputError("lattice") when `owned` is not inside the lattice.
  LocalStencils(const LatticeStencils<D, C>& stencils, const Box<D>& owned, const Box<D>& local);

  const Box<D>& owned() const { return owned_; }
  const Box<D>& local() const { return local_; }

  // y (C values per owned node, in the owned box's order) = the owned rows applied to x (C values
  // per node of the local box, in its order). OpenMP-parallel over lines along x. `direct`, when
  // given, marks the row types whose middle of line is computed row by row, as the serial
  // LatticeStencils::forEachProduct does for its `direct` types (the dashpot rows of a fused solve).
  // `lines` as forEachProduct's (below): the rows of the other lines are left as they are in y.
  void multiply(const Real* x, Real* y, const std::vector<char>* direct = nullptr,
                OwnedLines lines = OwnedLines::All) const;
  // The products one by one, as LatticeStencils::forEachProduct gives the serial ones: f(k, type,
  // product, stride) for every owned node k (the owned box's order) with its row applied to x,
  // component c at product[c * stride]; a line's middle goes row by row when direct(type) holds.
  // f must only write what belongs to node k (lines run on threads). `lines` picks the owned lines
  // (each is visited whole, so every row is the same whichever part computes it).
  template <class Function, class Direct>
  void forEachProduct(const Real* x, Function&& f, Direct&& direct, OwnedLines lines = OwnedLines::All) const;

  // Whether the rows of the owned line starting at node g (x = owned().lo[0]) read a halo node.
  bool lineReadsHalo(const std::array<Index, D>& g) const {
    if (xReadsHalo_) return true;
    for (int a = 1; a < D; ++a) {
      const auto s = static_cast<std::size_t>(a);
      if (g[s] < inner_.lo[s] || g[s] >= inner_.hi[s]) return true;
    }
    return false;
  }

 private:
  const LatticeStencils<D, C>* stencils_;
  Box<D> owned_, local_;
  std::vector<Index> flat_;  // per entry: the offset as a node-index difference in the local box
  std::uint64_t table_ = 0;  // stencil numbers of these offsets (freshStencilNumbers)
  // The owned nodes whose rows read no halo node along y and z; x: whether any row reads one.
  Box<D> inner_;
  bool xReadsHalo_ = false;
};

template <int D, int C>
template <class Function, class Direct>
void LocalStencils<D, C>::forEachProduct(const Real* x, Function&& f, Direct&& direct, OwnedLines which) const {
  const LatticeStencils<D, C>& stencils = *stencils_;
  const LatticeRowTypes<D>& types = stencils.types();
  const Index nx = types.nodes()[0], depth = types.depth();
  const bool runs = types.compactNodes()[0] < nx;  // else every x position is its own type
  // The middle of the lattice's lines (one type) within the owned x range: the serial product's runs.
  const Index middleFirst = runs ? std::max(owned_.lo[0], depth) : owned_.hi[0];
  const Index middleLast = runs ? std::min(owned_.hi[0], nx - depth) : owned_.hi[0];
  const long lines = static_cast<long>(owned_.lineCount());
  const std::uint64_t pass = nextStencilProduct();
#pragma omp parallel for schedule(static) if (lines > 16 && owned_.count() > 20000)
  for (long line = 0; line < lines; ++line) {
    const std::array<Index, D> g = owned_.lineStart(line);
    if (which != OwnedLines::All && lineReadsHalo(g) != (which == OwnedLines::WithHalo)) continue;
    Index base = 0, stride = types.compactNodes()[0];
    for (int a = 1; a < D; ++a) {
      const auto s = static_cast<std::size_t>(a);
      base += stride * types.compactIndex(a, g[s]);
      stride *= types.compactNodes()[s];
    }
    const Index in = local_.localIndex(g) - owned_.lo[0];  // node i of the line in x, and in the owned box
    const Index out = owned_.localIndex(g) - owned_.lo[0];
    Real product[C];
    auto single = [&](Index i) {
      const Index type = base + types.compactIndex(0, i);
      stencils.rowProductAt(type, x + C * (in + i), flat_.data(), product);
      f(out + i, type, static_cast<const Real*>(product), Index{1});
    };
    for (Index i = owned_.lo[0]; i < std::min(middleFirst, owned_.hi[0]); ++i) single(i);
    if (middleLast > middleFirst) {
      const Index type = base + depth, count = middleLast - middleFirst;
      if (direct(type)) {
        for (Index i = middleFirst; i < middleLast; ++i) single(i);
      } else {
        // The type's stencil with the local box's offsets, under this table's own numbers.
        StencilView view = stencils.view(type);
        view.flat = flat_.data() + stencils.begin(type);
        view.table = table_ + static_cast<std::uint64_t>(type);
        thread_local StencilRunCache cache;
        thread_local std::vector<Real> run;
        if (run.size() < static_cast<std::size_t>(C * count)) run.resize(static_cast<std::size_t>(C * count));
        stencilRun<C>(view, x, in + middleFirst, count, run.data(), cache, pass);
        for (Index l = 0; l < count; ++l) f(out + middleFirst + l, type, static_cast<const Real*>(run.data() + l), count);
      }
    }
    for (Index i = std::max(middleLast, middleFirst); i < owned_.hi[0]; ++i) single(i);
  }
}

extern template class LocalStencils<1>;
extern template class LocalStencils<2>;
extern template class LocalStencils<3>;
extern template class LocalStencils<2, 1>;
extern template class LocalStencils<3, 1>;

}  // namespace mfwave
