#pragma once
// The Galerkin variant of the very weak SPH on any solid (issue 48): the tent kernel of a box
// lattice (GalerkinLattice.hpp) integrated over the inside of each lattice cell, so the solid's
// surface may cut cells anywhere, and materials may change inside a cell.
//
// The weak form is the lattice's: K_ab = int_solid grad W_a : C(x) : grad W_b, M_a = int rho(x) W_a
// (lumped), dashpots rho c int_face W_a on the box faces the solid meets, loads int W_a t on its
// surface. Only the domain of the integrals changes. Each cell is integrated by the tensor 2-point
// Gauss rule (exact for the products of tents) on the parts of it that are wholly inside one
// material, found by subdividing the cells the surface or an interface cuts (2^depth sub-cells per
// axis); at the last level each Gauss point counts when it is inside (an error in the cut volume of
// order spacing / 2^depth).
//
// Small cut cells. A node outside the solid whose tent barely reaches into it has a tiny mass while
// its stiffness row is that of a gradient of size 1 / dx: its frequency grows without bound as the cut
// shrinks, and so would the explicit step's cost. A node whose volume int_solid W_a is below
// `smallCellFraction` of what it has in the uncut box is therefore not an unknown: its displacement
// is the bilinear (trilinear) extrapolation of the nearest lattice cell whose corners are all
// unknowns, u = E u~. The system is E^T K E, E^T C E and a lumped mass: each extended node's mass
// shared among the unknowns it is made of in proportion to its positive weights (the total kept;
// the row sums of E^T M E, with the extrapolation's negative weights, can be negative). E^T K E is
// symmetric positive
// semi-definite when K is, so the step is bounded by the unknowns' own rows: measured, the stable
// step stays within the fraction stated in docs/theory/very-weak-sph.md ("Cut cells") of the uncut
// lattice's. Staircasing (`cells = Staircase`: whole cells whose centre is inside) is the baseline
// it is compared with.

#include "core/Material.hpp"
#include "core/Types.hpp"

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace mfwave {

template <int D>
struct CutCellDomain {
  // The solid inside the lattice box: signed distance, < 0 inside (exact, or a bound with the right
  // sign that is exact on the surface). Required.
  std::function<Real(const Vec<D>&)> distance;
  // Its materials, the index of the one at an inside point, and a bound on the distance to the
  // nearest interface between two of them (empty: one material).
  std::vector<Material> materials;
  std::function<int(const Vec<D>&)> materialAt;
  std::function<Real(const Vec<D>&)> interfaceDistance;
};

enum class CutCells { Cut, Staircase };

template <int D>
struct CutCellSettings {
  Vec<D> lower = Vec<D>::Zero(), upper = Vec<D>::Zero();  // the lattice box
  Real spacing = 0;
  CutCells cells = CutCells::Cut;
  int depth = 4;                    // subdivision levels of a cut cell
  Real smallCellFraction = 0.25;    // below it a node is extended from its neighbours
  std::uint8_t transmittingFaces = 0;  // box faces (faceBit) with Lysmer-Kuhlemeyer dashpots
};

// A point of the solid's surface with its quadrature weight (length in 2-D, area in 3-D) and outward
// normal: what surface loads are integrated over.
template <int D>
struct SurfacePoint {
  Vec<D> x;
  Vec<D> normal;
  Real weight;
};

template <int D>
class CutCellGalerkin {
 public:
  // Throws InputError("geometry") when the solid has no cell inside the box, or a node to extend
  // finds no cell of unknowns within two spacings and no unknown within three (a feature thinner
  // than the lattice resolves);
  // InputError("material") for a point without a material.
  CutCellGalerkin(CutCellDomain<D> domain, const CutCellSettings<D>& settings);

  // The unknowns: D per unknown node, interleaved.
  Index unknownNodes() const { return static_cast<Index>(unknownPosition_.size()); }
  Index size() const { return D * unknownNodes(); }
  const std::vector<Vec<D>>& unknownPositions() const { return unknownPosition_; }
  const SparseMatrix& mass() const { return mass_; }
  const SparseMatrix& damping() const { return damping_; }  // 0 x 0 without transmitting faces
  const SparseMatrix& stiffness() const { return stiffness_; }

  // E^T f of nodal forces: a point force F at x (int W_a F delta), a moment-tensor point source
  // (the body force -M grad delta: f_a = M grad W_a(x)), and a surface traction t(x, n) on the surface
  // points `on` selects.
  Vector pointForce(const Vec<D>& x, const Vec<D>& force) const;
  Vector momentTensor(const Vec<D>& x, const Mat<D>& moment) const;
  Vector surfaceTraction(const std::function<bool(const Vec<D>&)>& on,
                         const std::function<Vec<D>(const Vec<D>& x, const Vec<D>& normal)>& traction) const;
  // The solid's surface inside cut cells: in 2-D segments by marching squares on the last level's
  // sub-cells, two Gauss points each; in 3-D one point per cut sub-cell, the tangent plane's area in
  // it (geometry/PlaneCut); with staircase cells, the faces between kept cells and cells left out,
  // 2^(D-1) Gauss points each.
  const std::vector<SurfacePoint<D>>& surface() const { return surface_; }

  // The field at x as a row over the unknown dofs: component `component` of sum_a W_a(x) u_a.
  std::vector<std::pair<Index, Real>> interpolation(const Vec<D>& x, int component) const;

  // What the cut did: the solid's integrated volume, cells cut, nodes extended, and the smallest
  // volume fraction kept as an unknown.
  Real volume() const { return volume_; }
  Index cutCells() const { return cutCells_; }
  Index extendedNodes() const { return extendedNodes_; }
  // Of those, the ones carried by their nearest unknown alone (no cell of unknowns within two
  // spacings: the tip of a sharp wedge).
  Index constantExtensions() const { return constantExtensions_; }
  Real smallestKeptFraction() const { return smallestKept_; }

 private:
  struct Point {
    Vec<D> x;
    Real weight;
    int material;
  };
  // The lattice: nodes per axis and linear node numbers (x fastest).
  Index nodeIndex(const std::array<Index, D>& node) const;
  std::array<Index, D> nodeOf(Index index) const;
  Vec<D> position(const std::array<Index, D>& node) const;
  // Quadrature points of the part of a cell (or sub-cell) inside the solid, split by material.
  void cellPoints(const Vec<D>& lower, Real size, int level, std::vector<Point>& out, bool& cut);
  // Rows of E over the active nodes' dofs: (unknown dof, weight) per active node component.
  void addExtended(std::vector<Triplet>& out, Index activeNode, int component, Real value, Index column) const;
  // Nodal force vector over active nodes, reduced by E^T.
  Vector reduce(const std::vector<std::pair<Index, Vec<D>>>& nodal) const;

  CutCellDomain<D> domain_;
  CutCellSettings<D> settings_;
  std::array<Index, D> nodes_{};
  std::vector<Index> active_;        // per lattice node: its active number or -1
  std::vector<Index> activeNode_;    // per active node: its lattice node
  // per active node: its unknown node, or -1 when extended; and the extension (unknown node, weight)
  std::vector<Index> unknownOf_;
  std::vector<std::vector<std::pair<Index, Real>>> extension_;
  std::vector<Vec<D>> unknownPosition_;
  SparseMatrix mass_, damping_, stiffness_;
  std::vector<SurfacePoint<D>> surface_;
  Real volume_ = 0;
  Index cutCells_ = 0, extendedNodes_ = 0, constantExtensions_ = 0;
  Real smallestKept_ = 1;
};

extern template class CutCellGalerkin<2>;
extern template class CutCellGalerkin<3>;

}  // namespace mfwave
