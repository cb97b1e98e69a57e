#pragma once
// Symmetry planes on a box lattice: the modelled lattice is one side of a mirror-symmetric solid,
// and its operators are the whole solid's restricted to mirror-symmetric fields.
//
// A symmetry face (zero normal displacement, zero tangential traction) at a box face is a mirror:
// the solid, its loads and its solution continue as their mirror images beyond it. The whole
// (mirrored) lattice has 2 n - 1 nodes along each symmetry axis; a symmetric field on it is
// u(x') = R u(x) with x' the image of x and R the reflection, which flips the normal component.
// With P the expansion of a field on the modelled nodes to the whole lattice, the restricted system
// is P^T M P, P^T K P, P^T C P, P^T f (the Galerkin restriction): symmetric whenever K is, with the
// whole solid's energy. Row by row: a node's row is its whole-lattice row with each column at an
// image node added into the column of the node it images (times the reflection's sign on the
// flipped component), multiplied by the node's multiplicity (2 per symmetry plane it is off). The
// multiplicities are powers of two, so M^-1 K u has the same bits as the unweighted fold.
//
// On a symmetry plane the normal displacement of a symmetric field is zero; those dofs are inert:
// their rows and columns are dropped but for the diagonal (the mass stays invertible), so they keep
// their initial zero exactly.
//
// Nodes are numbered x fastest (LatticeRowTypes.hpp), D dofs per node, one per axis.

#include "core/Types.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace mfwave {

// The mask of the whole (mirrored) box's faces that carry what `faces` names on the modelled box:
// each symmetry face's bit is replaced by its opposite face's (the image of the far face), and the
// symmetry faces themselves are interior.
std::uint8_t mirroredFaceMask(std::uint8_t faces, std::uint8_t symmetryFaces, int dimension);

// Throws InputError(key) when both faces of one axis are symmetry faces (an infinite or periodic
// repetition, not a mirror).
void checkSymmetryFaces(std::uint8_t symmetryFaces, int dimension, const char* key);

template <int D>
class SymmetryFold {
 public:
  SymmetryFold() = default;
  // `nodes` per axis on the modelled lattice, `symmetryFaces` a faceBit mask (checkSymmetryFaces).
  SymmetryFold(const std::array<Index, D>& nodes, std::uint8_t symmetryFaces);

  bool active() const { return symmetry_ != 0; }
  std::uint8_t symmetryFaces() const { return symmetry_; }
  // Nodes per axis of the whole lattice (2 n - 1 along each symmetry axis).
  const std::array<Index, D>& wholeNodes() const { return whole_; }
  // The whole lattice's lower corner from the modelled one's, in spacings (<= 0 per axis).
  std::array<Index, D> wholeOriginShift() const;

  // The Galerkin restriction P^T A P of an operator assembled on the whole lattice (D dofs per
  // node), inert dofs dropped.
  SparseMatrix restrictOperator(const SparseMatrix& whole) const;
  // The fold without the multiplicities (A P restricted to the modelled rows): for maps that act on
  // the field itself rather than a balance of forces (the smoothing filter, the deconvolution).
  SparseMatrix foldMap(const SparseMatrix& whole) const;
  // P^T f of a force on the whole lattice's dofs, inert dofs zero.
  Vector restrictForce(const Vector& whole) const;
  // The multiplicity of a modelled node (2^(symmetry planes it is off)), and whether a modelled dof
  // (node * D + component) is inert.
  Real multiplicity(const std::array<Index, D>& node) const;
  bool inert(const std::array<Index, D>& node, int component) const;

 private:
  SparseMatrix fold(const SparseMatrix& whole, bool weighted) const;

  std::array<Index, D> nodes_{};
  std::array<Index, D> whole_{};
  std::uint8_t symmetry_ = 0;
};

extern template class SymmetryFold<1>;
extern template class SymmetryFold<2>;
extern template class SymmetryFold<3>;

}  // namespace mfwave
