#pragma once
// An operator on a box lattice stored as one stencil per row type (LatticeRowTypes) instead of one
// row per node: each stencil is a list of (lattice offset, C x C block), the block coupling the
// node's C components to those of the node at the offset (C = D for displacements, C = 1 for a
// scalar field such as the finite-difference wave's). A node's row is its type's stencil,
// addressed by lattice arithmetic: no neighbour list, no per-row storage. On a 3-D block the
// whole table is a few hundred stencils whatever the lattice size.
//
// The table is read off an operator assembled on the compact lattice of the row types (the same
// method, the same faces, 2 depth + 1 nodes per axis), so the method's own assembly stays the one
// definition of every row; mismatch() checks it against an assembly on a larger lattice.
//
// Products are OpenMP-parallel over lattice lines; every row is summed in the same order whatever
// the thread count, so results are bitwise the same on any number of threads.

#include "core/Types.hpp"
#include "lattice/LatticeRowTypes.hpp"
#include "lattice/StencilRun.hpp"

#include <array>
#include <cstddef>
#include <utility>
#include <vector>

namespace mfwave {

template <int D, int C = D>
class LatticeStencils {
 public:
  LatticeStencils() = default;
  // The stencils of `compact`, assembled on the compact lattice of `types` (rows and columns
  // node * C + component), addressed on the lattice of `types`. Throws InputError("lattice") when
  // the matrix has the wrong size.
  LatticeStencils(const LatticeRowTypes<D>& types, const SparseMatrix& compact);

  const LatticeRowTypes<D>& types() const { return types_; }
  bool empty() const { return offset_.empty(); }
  Index typeCount() const { return static_cast<Index>(start_.size()) - 1; }
  Index entryCount() const { return static_cast<Index>(offset_.size()); }
  Index begin(Index type) const { return start_[static_cast<std::size_t>(type)]; }
  Index end(Index type) const { return start_[static_cast<std::size_t>(type) + 1]; }
  const std::array<Index, D>& offset(Index entry) const { return offset_[static_cast<std::size_t>(entry)]; }
  // The C x C block of an entry, row-major.
  const Real* block(Index entry) const { return &block_[static_cast<std::size_t>(C * C * entry)]; }
  // The sum of a type's blocks, row-major C x C (zero for an empty table): for a block-diagonal
  // operator (mass, lumped dashpots), its block at that type.
  void typeSum(Index type, Real* out) const;
  // True when every entry sits at offset zero (a block-diagonal operator: mass, lumped dashpots).
  bool blockDiagonal() const;
  // The same stencils addressed on the lattice of `types` (same depth, any size).
  LatticeStencils on(const LatticeRowTypes<D>& types) const;
  // Bytes of the table.
  std::size_t bytes() const;

  // y = A x and the row sums of |A|, over the whole lattice.
  void multiply(const Vector& x, Vector& y) const;
  Vector absoluteRowSums() const;
  // The row sums of |A| per row type, C values each (what absoluteRowSums gives each node).
  std::vector<Real> absoluteRowSumsPerType() const;
  // The operator as a sparse matrix (for checks on small lattices).
  SparseMatrix toSparse() const;
  // max |A_stencil - matrix| / max |matrix| for `matrix` assembled on the lattice of types() by the
  // same method: 0 (up to round-off) when the stencils give every row of it.
  Real mismatch(const SparseMatrix& matrix) const;

  // Each entry's offset as a node-index difference in an array of `storage` nodes per axis (x
  // fastest): the lattice's own (bind) or a rank's local box (lib/decomposition/LocalStencils).
  std::vector<Index> flatOffsets(const std::array<Index, D>& storage) const;

  // The node an entry of node p's row reads.
  Index column(Index entry, Index p) const { return p + flat_[static_cast<std::size_t>(entry)]; }
  // The stencil of a type, for stencilRun.
  StencilView view(Index type) const {
    const auto b = static_cast<std::size_t>(begin(type));
    return {block_.data() + C * C * b, flat_.data() + b, dx_.data() + b, end(type) - begin(type),
            table_ + static_cast<std::uint64_t>(type)};
  }

  // Calls f(p, type, product, stride) for every node p with the row applied to x: component c of
  // (A x)_p is product[c * stride]. Lines along x run in parallel (forEachLatticeLine); the middle
  // of each line, where the type is the same, goes through stencilRun. `direct(type)` true keeps a
  // run's nodes on the per-node path (the caller's choice, e.g. where it adds a second stencil).
  template <class Function, class Direct>
  void forEachProduct(const Real* x, Function&& f, Direct&& direct) const;
  template <class Function>
  void forEachProduct(const Real* x, Function&& f) const {
    forEachProduct(x, std::forward<Function>(f), [](Index) { return false; });
  }

  // The row of node p (of type `type`) applied to x: out[c] = sum_e sum_d B_e[c][d] x[C (p + o_e) + d].
  void rowProduct(Index type, Index p, const Real* x, Real* out) const { rowProductAt(type, x + C * p, flat_.data(), out); }
  // The same sum with the node's values at xNode and the entries' node offsets `flat` (indexed by
  // entry): this table's, or those of another storage of the same lattice (a rank's local box,
  // lib/decomposition/LocalStencils), so that both sum every row in one order.
  void rowProductAt(Index type, const Real* xNode, const Index* flat, Real* out) const {
    Real acc[C] = {};
    for (Index e = start_[static_cast<std::size_t>(type)]; e < start_[static_cast<std::size_t>(type) + 1]; ++e) {
      const Real* b = &block_[static_cast<std::size_t>(C * C * e)];
      const Real* xe = xNode + C * flat[e];
      for (int c = 0; c < C; ++c)
        for (int d = 0; d < C; ++d) acc[c] += b[C * c + d] * xe[d];
    }
    for (int c = 0; c < C; ++c) out[c] = acc[c];
  }

 private:
  void bind();  // flat offsets on types_'s lattice

  LatticeRowTypes<D> types_;
  std::vector<Index> start_;                  // typeCount + 1
  std::vector<std::array<Index, D>> offset_;  // per entry
  std::vector<Real> block_;                   // C * C per entry
  std::vector<Index> flat_;                   // per entry: the offset as a node-index difference
  std::vector<Index> dx_;                     // per entry: the offset's x part
  std::uint64_t table_ = 0;                   // the first of its stencils' numbers (freshStencilNumbers)
};

// Calls f(first, base) for every line of nodes along x: first is its first node, base the type of
// its nodes without the x part (type = base + compactIndex(0, i)). OpenMP-parallel over lines in a
// fixed static partition.
template <int D, class Function>
void forEachLatticeLine(const LatticeRowTypes<D>& types, Function&& f) {
  const Index nx = types.nodes()[0];
  const long lines = static_cast<long>(types.nodeCount() / nx);
#pragma omp parallel for schedule(static) if (lines > 16 && types.nodeCount() > 20000)
  for (long line = 0; line < lines; ++line) {
    Index rest = line, base = 0, stride = types.compactNodes()[0];
    for (int a = 1; a < D; ++a) {
      const auto s = static_cast<std::size_t>(a);
      base += stride * types.compactIndex(a, rest % types.nodes()[s]);
      rest /= types.nodes()[s];
      stride *= types.compactNodes()[s];
    }
    f(static_cast<Index>(line) * nx, base);
  }
}

// Calls f(p, type) for every node p of the lattice (x fastest), OpenMP-parallel over lines along x;
// f must only write what belongs to node p. Lines are visited in a fixed partition, so per-line
// results are the same on any thread count.
template <int D, class Function>
void forEachLatticeNode(const LatticeRowTypes<D>& types, Function&& f) {
  const Index nx = types.nodes()[0];
  forEachLatticeLine<D>(types, [&](Index first, Index base) {
    for (Index i = 0; i < nx; ++i) f(first + i, base + types.compactIndex(0, i));
  });
}

template <int D, int C>
template <class Function, class Direct>
void LatticeStencils<D, C>::forEachProduct(const Real* x, Function&& f, Direct&& direct) const {
  const Index nx = types_.nodes()[0], depth = types_.depth();
  const bool runs = types_.compactNodes()[0] < nx;  // else every x position is its own type
  const std::uint64_t pass = nextStencilProduct();
  forEachLatticeLine<D>(types_, [&](Index first, Index base) {
    Real product[C];
    auto single = [&](Index i) {
      const Index type = base + types_.compactIndex(0, i);
      rowProduct(type, first + i, x, product);
      f(first + i, type, product, Index{1});
    };
    if (!runs) {
      for (Index i = 0; i < nx; ++i) single(i);
      return;
    }
    for (Index i = 0; i < depth; ++i) single(i);
    const Index type = base + depth, length = nx - 2 * depth;
    if (direct(type)) {
      for (Index i = depth; i < nx - depth; ++i) single(i);
    } else {
      thread_local StencilRunCache cache;
      thread_local std::vector<Real> run;
      if (run.size() < static_cast<std::size_t>(C * length)) run.resize(static_cast<std::size_t>(C * length));
      stencilRun<C>(view(type), x, first + depth, length, run.data(), cache, pass);
      for (Index l = 0; l < length; ++l) f(first + depth + l, type, run.data() + l, length);
    }
    for (Index i = nx - depth; i < nx; ++i) single(i);
  });
}

// sum over nodes of g(p, type), summed per line and then over lines in order: bitwise the same on
// any thread count.
template <int D, class Function>
Real sumOverLatticeNodes(const LatticeRowTypes<D>& types, Function&& g) {
  const Index nx = types.nodes()[0];
  std::vector<Real> lineSums(static_cast<std::size_t>(types.nodeCount() / nx), 0.0);
  forEachLatticeNode<D>(types, [&](Index p, Index type) { lineSums[static_cast<std::size_t>(p / nx)] += g(p, type); });
  Real sum = 0;
  for (Real s : lineSums) sum += s;
  return sum;
}

extern template class LatticeStencils<1>;
extern template class LatticeStencils<2>;
extern template class LatticeStencils<3>;
extern template class LatticeStencils<2, 1>;  // scalar fields
extern template class LatticeStencils<3, 1>;

}  // namespace mfwave
