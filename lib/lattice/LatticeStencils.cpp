#include "lattice/LatticeStencils.hpp"

#include "core/Error.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

namespace mfwave {

template <int D, int C>
LatticeStencils<D, C>::LatticeStencils(const LatticeRowTypes<D>& types, const SparseMatrix& compact) : types_(types) {
  const LatticeRowTypes<D> compactTypes(types.compactNodes(), types.depth());
  const Index nodes = compactTypes.nodeCount();
  if (compact.rows() != C * nodes || compact.cols() != C * nodes)
    throw InputError("lattice", "the compact operator is " + std::to_string(compact.rows()) + " x " +
                                    std::to_string(compact.cols()) + ", the compact lattice has " +
                                    std::to_string(C * nodes) + " unknowns");
  // Per compact node (= type): offset -> block, offsets ordered like node indices (z, y, x).
  using Offset = std::array<Index, D>;
  auto before = [](const Offset& a, const Offset& b) {
    for (int k = D - 1; k >= 0; --k)
      if (a[static_cast<std::size_t>(k)] != b[static_cast<std::size_t>(k)])
        return a[static_cast<std::size_t>(k)] < b[static_cast<std::size_t>(k)];
    return false;
  };
  std::vector<std::map<Offset, std::array<Real, C * C>, decltype(before)>> rows(
      static_cast<std::size_t>(nodes), std::map<Offset, std::array<Real, C * C>, decltype(before)>(before));
  for (int k = 0; k < compact.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(compact, k); it; ++it) {
      if (it.value() == 0) continue;
      const Index rowNode = it.row() / C, colNode = it.col() / C;
      const std::array<Index, D> r = compactTypes.node(rowNode), c = compactTypes.node(colNode);
      Offset o{};
      for (int a = 0; a < D; ++a) o[static_cast<std::size_t>(a)] = c[static_cast<std::size_t>(a)] - r[static_cast<std::size_t>(a)];
      auto [entry, fresh] = rows[static_cast<std::size_t>(rowNode)].try_emplace(o);
      if (fresh) entry->second.fill(0);
      entry->second[static_cast<std::size_t>(C * (it.row() % C) + it.col() % C)] = it.value();
    }
  start_.assign(1, 0);
  for (const auto& row : rows) {
    for (const auto& [o, b] : row) {
      offset_.push_back(o);
      block_.insert(block_.end(), b.begin(), b.end());
    }
    start_.push_back(static_cast<Index>(offset_.size()));
  }
  bind();
}

template <int D, int C>
void LatticeStencils<D, C>::bind() {
  table_ = freshStencilNumbers(static_cast<std::uint64_t>(std::max<Index>(typeCount(), 1)));
  flat_ = flatOffsets(types_.nodes());
  dx_.resize(offset_.size());
  for (std::size_t e = 0; e < offset_.size(); ++e) dx_[e] = offset_[e][0];
}

template <int D, int C>
std::vector<Index> LatticeStencils<D, C>::flatOffsets(const std::array<Index, D>& storage) const {
  std::vector<Index> flat(offset_.size());
  for (std::size_t e = 0; e < offset_.size(); ++e) {
    Index f = 0;
    for (int a = D - 1; a >= 0; --a) f = f * storage[static_cast<std::size_t>(a)] + offset_[e][static_cast<std::size_t>(a)];
    flat[e] = f;
  }
  return flat;
}

template <int D, int C>
LatticeStencils<D, C> LatticeStencils<D, C>::on(const LatticeRowTypes<D>& types) const {
  if (types.depth() != types_.depth() || types.typeCount() != types_.typeCount())
    throw InputError("lattice", "stencils of depth " + std::to_string(types_.depth()) + " and " +
                                    std::to_string(types_.typeCount()) + " types moved to a lattice with " +
                                    std::to_string(types.typeCount()) + " types at depth " + std::to_string(types.depth()));
  LatticeStencils moved = *this;
  moved.types_ = types;
  moved.bind();
  return moved;
}

template <int D, int C>
void LatticeStencils<D, C>::typeSum(Index type, Real* out) const {
  for (int k = 0; k < C * C; ++k) out[k] = 0;
  if (empty()) return;
  for (Index e = begin(type); e < end(type); ++e)
    for (int k = 0; k < C * C; ++k) out[k] += block(e)[k];
}

template <int D, int C>
bool LatticeStencils<D, C>::blockDiagonal() const {
  for (const auto& o : offset_)
    for (Index v : o)
      if (v != 0) return false;
  return true;
}

template <int D, int C>
std::size_t LatticeStencils<D, C>::bytes() const {
  return start_.size() * sizeof(Index) + offset_.size() * (sizeof(std::array<Index, D>) + 2 * sizeof(Index)) +
         block_.size() * sizeof(Real);
}

template <int D, int C>
void LatticeStencils<D, C>::multiply(const Vector& x, Vector& y) const {
  y.resize(C * types_.nodeCount());
  Real* out = y.data();
  forEachProduct(x.data(), [&](Index p, Index, const Real* product, Index stride) {
    for (int c = 0; c < C; ++c) out[C * p + c] = product[c * stride];
  });
}

template <int D, int C>
std::vector<Real> LatticeStencils<D, C>::absoluteRowSumsPerType() const {
  std::vector<Real> sums(static_cast<std::size_t>(C * typeCount()), 0.0);
  for (Index type = 0; type < typeCount(); ++type)
    for (int c = 0; c < C; ++c) {
      Real s = 0;
      for (Index e = begin(type); e < end(type); ++e)
        for (int d = 0; d < C; ++d) s += std::abs(block(e)[C * c + d]);
      sums[static_cast<std::size_t>(C * type + c)] = s;
    }
  return sums;
}

template <int D, int C>
Vector LatticeStencils<D, C>::absoluteRowSums() const {
  const std::vector<Real> perType = absoluteRowSumsPerType();
  Vector sums(C * types_.nodeCount());
  forEachLatticeNode<D>(types_, [&](Index p, Index type) {
    for (int c = 0; c < C; ++c) sums[C * p + c] = perType[static_cast<std::size_t>(C * type + c)];
  });
  return sums;
}

template <int D, int C>
SparseMatrix LatticeStencils<D, C>::toSparse() const {
  const Index n = types_.nodeCount();
  std::vector<Triplet> entries;
  for (Index p = 0; p < n; ++p) {
    const Index type = types_.typeOf(types_.node(p));
    for (Index e = begin(type); e < end(type); ++e)
      for (int c = 0; c < C; ++c)
        for (int d = 0; d < C; ++d)
          if (block(e)[C * c + d] != 0)
            entries.emplace_back(static_cast<int>(C * p + c), static_cast<int>(C * (p + flat_[static_cast<std::size_t>(e)]) + d),
                                 block(e)[C * c + d]);
  }
  SparseMatrix m(C * n, C * n);
  m.setFromTriplets(entries.begin(), entries.end());
  return m;
}

template <int D, int C>
Real LatticeStencils<D, C>::mismatch(const SparseMatrix& matrix) const {
  const Real scale = matrix.nonZeros() > 0 ? matrix.coeffs().cwiseAbs().maxCoeff() : 0;
  if (matrix.rows() != C * types_.nodeCount()) return std::numeric_limits<Real>::infinity();
  const SparseMatrix difference = toSparse() - matrix;
  const Real largest = difference.nonZeros() > 0 ? difference.coeffs().cwiseAbs().maxCoeff() : 0;
  return scale > 0 ? largest / scale : largest;
}

template class LatticeStencils<1>;
template class LatticeStencils<2>;
template class LatticeStencils<3>;
template class LatticeStencils<2, 1>;
template class LatticeStencils<3, 1>;

}  // namespace mfwave
