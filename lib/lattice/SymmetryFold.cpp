#include "lattice/SymmetryFold.hpp"

#include "core/Error.hpp"

#include <string>

namespace mfwave {
namespace {

// Faces are numbered 2 axis + side (side 0 the low face, 1 the high: particles/BoxFace.hpp).
constexpr std::uint8_t bitOf(int face) { return static_cast<std::uint8_t>(1u << face); }
constexpr int opposite(int face) { return face ^ 1; }

}  // namespace

std::uint8_t mirroredFaceMask(std::uint8_t faces, std::uint8_t symmetryFaces, int dimension) {
  std::uint8_t out = static_cast<std::uint8_t>(faces & ~symmetryFaces);
  for (int face = 0; face < 2 * dimension; ++face)
    if ((symmetryFaces & bitOf(face)) != 0 && (faces & bitOf(opposite(face))) != 0)
      out = static_cast<std::uint8_t>(out | bitOf(face));
  return out;
}

void checkSymmetryFaces(std::uint8_t symmetryFaces, int dimension, const char* key) {
  static const char* const axes[] = {"x", "y", "z"};
  for (int axis = 0; axis < dimension; ++axis)
    if ((symmetryFaces & bitOf(2 * axis)) != 0 && (symmetryFaces & bitOf(2 * axis + 1)) != 0)
      throw InputError(key, std::string("both faces of axis ") + axes[axis] +
                                " are symmetry planes: a mirror on each side repeats the solid without end; "
                                "make one of them a boundary of the solid");
  if ((symmetryFaces >> (2 * dimension)) != 0)
    throw InputError(key, "a symmetry face beyond the box's " + std::to_string(2 * dimension) + " faces");
}

template <int D>
SymmetryFold<D>::SymmetryFold(const std::array<Index, D>& nodes, std::uint8_t symmetryFaces)
    : nodes_(nodes), whole_(nodes), symmetry_(symmetryFaces) {
  checkSymmetryFaces(symmetryFaces, D, "boundary");
  for (int a = 0; a < D; ++a) {
    const auto s = static_cast<std::size_t>(a);
    if (nodes[s] < 1) throw InputError("lattice", "an axis without nodes");
    if ((symmetry_ & (bitOf(2 * a) | bitOf(2 * a + 1))) != 0) whole_[s] = 2 * nodes[s] - 1;
  }
}

template <int D>
std::array<Index, D> SymmetryFold<D>::wholeOriginShift() const {
  std::array<Index, D> shift{};
  for (int a = 0; a < D; ++a)
    if ((symmetry_ & bitOf(2 * a)) != 0) shift[static_cast<std::size_t>(a)] = -(nodes_[static_cast<std::size_t>(a)] - 1);
  return shift;
}

template <int D>
Real SymmetryFold<D>::multiplicity(const std::array<Index, D>& node) const {
  Real m = 1;
  for (int a = 0; a < D; ++a) {
    const auto s = static_cast<std::size_t>(a);
    if ((symmetry_ & bitOf(2 * a)) != 0 && node[s] != 0) m *= 2;
    if ((symmetry_ & bitOf(2 * a + 1)) != 0 && node[s] != nodes_[s] - 1) m *= 2;
  }
  return m;
}

template <int D>
bool SymmetryFold<D>::inert(const std::array<Index, D>& node, int component) const {
  const auto s = static_cast<std::size_t>(component);
  return ((symmetry_ & bitOf(2 * component)) != 0 && node[s] == 0) ||
         ((symmetry_ & bitOf(2 * component + 1)) != 0 && node[s] == nodes_[s] - 1);
}

template <int D>
SparseMatrix SymmetryFold<D>::fold(const SparseMatrix& whole, bool weighted) const {
  Index wholeCount = 1, count = 1;
  for (int a = 0; a < D; ++a) {
    wholeCount *= whole_[static_cast<std::size_t>(a)];
    count *= nodes_[static_cast<std::size_t>(a)];
  }
  if (whole.rows() != D * wholeCount || whole.cols() != D * wholeCount)
    throw InputError("lattice", "the operator to fold is not on the whole lattice of the symmetry planes");
  // Per whole node: its modelled node (linear), the axes it is reflected across (a bit mask), and
  // whether it is itself a modelled node.
  std::vector<Index> target(static_cast<std::size_t>(wholeCount));
  std::vector<unsigned> reflected(static_cast<std::size_t>(wholeCount));
  std::vector<std::array<Index, D>> modelled(static_cast<std::size_t>(wholeCount));
  for (Index p = 0; p < wholeCount; ++p) {
    Index rest = p, index = 0, stride = 1;
    unsigned flips = 0;
    std::array<Index, D> node{};
    for (int a = 0; a < D; ++a) {
      const auto s = static_cast<std::size_t>(a);
      Index i = rest % whole_[s];
      rest /= whole_[s];
      if ((symmetry_ & bitOf(2 * a)) != 0) {
        i -= nodes_[s] - 1;
        if (i < 0) { i = -i; flips |= 1u << a; }
      } else if ((symmetry_ & bitOf(2 * a + 1)) != 0 && i > nodes_[s] - 1) {
        i = 2 * (nodes_[s] - 1) - i;
        flips |= 1u << a;
      }
      node[s] = i;
      index += i * stride;
      stride *= nodes_[s];
    }
    target[static_cast<std::size_t>(p)] = index;
    reflected[static_cast<std::size_t>(p)] = flips;
    modelled[static_cast<std::size_t>(p)] = node;
  }
  std::vector<Triplet> entries;
  entries.reserve(static_cast<std::size_t>(whole.nonZeros()));
  for (int outer = 0; outer < whole.outerSize(); ++outer)
    for (SparseMatrix::InnerIterator it(whole, outer); it; ++it) {
      const auto rowNode = static_cast<std::size_t>(it.row() / D), colNode = static_cast<std::size_t>(it.col() / D);
      if (reflected[rowNode] != 0) continue;  // an image row: the modelled row it images carries it
      const int rowComponent = static_cast<int>(it.row() % D), colComponent = static_cast<int>(it.col() % D);
      // An inert dof keeps its diagonal alone (its mass stays, its force is K_ii 0 = 0).
      const bool diagonal = rowNode == colNode && rowComponent == colComponent;
      if (!diagonal && (inert(modelled[rowNode], rowComponent) || inert(modelled[colNode], colComponent))) continue;
      Real value = it.value();
      if ((reflected[colNode] >> colComponent) & 1u) value = -value;  // R flips the normal component
      if (weighted) value *= multiplicity(modelled[rowNode]);
      entries.emplace_back(static_cast<int>(D * target[rowNode] + rowComponent),
                           static_cast<int>(D * target[colNode] + colComponent), value);
    }
  SparseMatrix out(static_cast<Index>(D * count), static_cast<Index>(D * count));
  out.setFromTriplets(entries.begin(), entries.end());
  return out;
}

template <int D>
SparseMatrix SymmetryFold<D>::restrictOperator(const SparseMatrix& whole) const {
  return fold(whole, true);
}

template <int D>
SparseMatrix SymmetryFold<D>::foldMap(const SparseMatrix& whole) const {
  return fold(whole, false);
}

template <int D>
Vector SymmetryFold<D>::restrictForce(const Vector& whole) const {
  Index count = 1;
  for (int a = 0; a < D; ++a) count *= nodes_[static_cast<std::size_t>(a)];
  const std::array<Index, D> shift = wholeOriginShift();
  Vector out = Vector::Zero(D * count);
  for (Index p = 0; p < count; ++p) {
    Index rest = p, wholeIndex = 0, stride = 1;
    std::array<Index, D> node{};
    for (int a = 0; a < D; ++a) {
      const auto s = static_cast<std::size_t>(a);
      node[s] = rest % nodes_[s];
      rest /= nodes_[s];
      wholeIndex += (node[s] - shift[s]) * stride;
      stride *= whole_[s];
    }
    const Real m = multiplicity(node);
    for (int c = 0; c < D; ++c)
      if (!inert(node, c)) out[D * p + c] = m * whole[D * wholeIndex + c];
  }
  return out;
}

template class SymmetryFold<1>;
template class SymmetryFold<2>;
template class SymmetryFold<3>;

}  // namespace mfwave
