#pragma once
// Isotropic elasticity by the spectral-element method (SEM, as in SPECFEM2D / SPECFEM3D:
// Komatitsch & Vilotte 1998, Komatitsch & Tromp 1999), plane strain (D = 2) or 3-D (D = 3), one
// implementation for both: a structured mesh of equal square / cubic elements covering an
// axis-aligned box, Gauss-Lobatto-Legendre (GLL) nodes of order N along each axis, the
// tensor-product Lagrange basis on them and GLL quadrature. Because the quadrature points are the
// interpolation nodes, M is diagonal (lumped) without any lumping step, and an explicit central
// difference needs no solve.
//
//   unknowns      D displacement components per global GLL node, interleaved (u[D p + c]), nodes
//                 numbered x fastest, then y, then z (p = (k ny + j) nx + i), as the lattice
//                 systems lay them out
//   stiffness     matrix-free by sum factorisation (Deville, Fischer & Mund 2002, ch. 4; Komatitsch
//                 & Tromp 1999): per element the displacement gradient at the GLL points by the 1-D
//                 derivative matrix along each axis, the stress there (lambda tr(eps) I + 2 mu eps)
//                 times the quadrature weight and Jacobian, and the transposed derivative products
//                 back to the nodes: O(D^2 (N + 1)^(D + 1)) per element instead of the dense element
//                 matrix's (D (N + 1)^D)^2. Every element is the same cube with the same material, so
//                 one set of reference data serves all; elements in a fixed order (bitwise
//                 reproducible). The dense K_e is assembled column by column from that product:
//                 on request in 3-D (elementStiffness(), tests and the Gershgorin bound), and kept
//                 in 2-D, where its 50-square (N = 4) dense product is the faster one.
//   faces         free (natural), fixed (u = 0: those unknowns are masked out of K, f and the
//                 acceleration, so K stays symmetric), absorbing (Lysmer & Kuhlemeyer 1969
//                 dashpots: C diagonal, rho c_p on the normal and rho c_s on the tangential
//                 components, times the node's face GLL weights times the face Jacobian (h/2)^(D-1)),
//                 periodic (both faces of an axis: the last element's far nodes are the first
//                 element's near ones, so the axis has elements * N nodes and no face; the plane-wave
//                 study's periodic box)
//   loads         tractions T f(t) on a rectangle |x_t - centre_t| < halfWidth_t (t the face's
//                 tangential axes) of a face, integrated against each basis function exactly:
//                 tensor Gauss-Legendre of N + 1 points per axis over the loaded part of each face
//                 element (the face's GLL rule would do when the rectangle's edges are element
//                 boundaries; the Gauss rule is exact also when an edge falls inside an element)

#include "core/Material.hpp"
#include "particles/ParticleSet.hpp"
#include "systems/LinearOperatorSystem.hpp"

#include <array>
#include <functional>
#include <vector>

namespace mfwave {

enum class SpectralElementFace { Free, Fixed, Absorbing, Periodic };

template <int D>
struct SpectralElementTraction {
  int face = 2 * D - 1;                  // BoxFace number (0 -x, 1 +x, 2 -y, 3 +y, 4 -z, 5 +z)
  Vec<D> centre = Vec<D>::Zero();        // on the face (the normal component is not read)
  Vec<D> halfWidth = Vec<D>::Zero();     // along the tangential axes (the normal component is not read)
  Vec<D> traction = Vec<D>::Zero();      // Pa, constant on the rectangle
  std::function<Real(Real)> history;     // f(t)
};

template <int D>
struct SpectralElementSettings {
  Vec<D> lower = Vec<D>::Zero(), upper = Vec<D>::Zero();
  Real elementSize = 1;
  int order = 4;  // N: N + 1 GLL nodes per element edge
  Material material = Material::fromLame(1, 1, 1);
  // Materials by region (issue 48): empty for `material` everywhere; else `materialAt` gives, for an
  // element's centre, its index into `regionMaterials`. Each element has one material, so an
  // interface must lie on element boundaries (a layered box meshed by whole elements per layer): the
  // stiffness, mass and dashpots are integrated element by element with that element's (lambda,
  // mu, rho), and a node on an interface takes its share from each side. No averaging is needed.
  std::vector<Material> regionMaterials;
  std::function<int(const Vec<D>&)> materialAt;
  std::array<SpectralElementFace, 2 * D> faces = uniformFaces(SpectralElementFace::Free);
  std::vector<SpectralElementTraction<D>> tractions;

  static std::array<SpectralElementFace, 2 * D> uniformFaces(SpectralElementFace kind) {
    std::array<SpectralElementFace, 2 * D> f{};
    f.fill(kind);
    return f;
  }
};

// The number of elements of size h in `length`, or -1 when it is not a whole number of them (to
// 1e-9 relative): what the mesh requires of the box, and what a study checks before building one.
Index wholeElements(Real length, Real h);

template <int D>
class SpectralElementElasticity : public LinearOperatorSystem {
 public:
  using Nodes = std::array<Index, D>;

  // Throws InputError("order") outside 1..8, InputError("elementSize") when the box is not a
  // whole number of elements (or, along a periodic axis, an odd number above one: the parity
  // colouring of the element loop needs the first and last elements to differ in colour),
  // InputError("faces") for an axis periodic on one face only, InputError("traction") for a
  // rectangle outside its face, of no width, on a periodic face, or a traction without history.
  explicit SpectralElementElasticity(SpectralElementSettings<D> settings);

  Index size() const override { return D * nodeCount(); }
  bool hasDamping() const override { return hasDamping_; }
  void acceleration(Real t, Eigen::Ref<const Vector> u, Eigen::Ref<const Vector> v, Eigen::Ref<Vector> a) override;

  void force(Real t, Vector& f) const override;
  void applyStiffness(const Vector& x, Vector& y) const override;
  Real kineticEnergy(const Vector& v) const override;
  Real strainEnergy(const Vector& u) const override;
  Real dampingPower(const Vector& v) const override;
  Vector lumpedMass() const override { return mass_; }
  // An upper bound of sum_j |K_ij| (element by element with |K_e|), which keeps the Gershgorin
  // step safe.
  Vector stiffnessAbsoluteRowSums() const override;
  std::unique_ptr<CentredDampingSolve> centredDamping(Real dt, const std::vector<Index>& prescribedDofs) const override;

  Index nodeCount() const;
  Nodes nodesPerAxis() const { return nodes_; }
  Nodes elementsPerAxis() const { return elements_; }
  Index elementCount() const;
  Vec<D> nodePosition(Index node) const;
  // The global node at x, or -1 when no node is within 1e-9 element sizes of it.
  Index nodeAt(const Vec<D>& x) const;
  // The GLL nodes as particles: volume = the lumped mass over rho, face bits of the box faces a
  // node lies on (what the probes and the Lamb scores read).
  ParticleSet<D> nodeParticles() const;
  // The dense element matrix, D (N + 1)^D square, local dof D l + c with l = a + (N + 1)(b + (N + 1) c),
  // assembled column by column from the sum-factorised element product (tests, Gershgorin), of the
  // material numbered `material` (0: settings.material, or the first region's).
  Eigen::MatrixXd elementStiffness(int material = 0) const;
  // y_e = K_e x_e for one element's local vectors (layout as elementStiffness()), by sum factorisation.
  void elementProduct(const Real* x, Real* y, int material = 0) const;
  // The materials (settings.material alone, or the regions') and each element's.
  const std::vector<Material>& materials() const { return materials_; }
  int elementMaterial(Index e) const { return elementMaterial_.empty() ? 0 : elementMaterial_[static_cast<std::size_t>(e)]; }
  const Vector& dampingDiagonal() const { return damping_; }
  // 1 for the unknowns a fixed face holds at zero.
  const std::vector<char>& fixedDofs() const { return fixed_; }
  const SpectralElementSettings<D>& settings() const { return settings_; }
  // The GLL points of the reference element [-1, 1].
  const std::vector<Real>& referenceNodes() const { return gllNodes_; }

  // r = f(t) - K u - C v on every unknown (zero on fixed ones).
  void residual(Real t, const Real* u, const Real* v, Real* r) const;

 private:
  void buildReferenceData();
  void buildMassAndDamping();
  void buildLoads();
  // The first global node of element `e` (its local node 0).
  Index elementBase(Index e) const;
  // The global node of each of element e's (N + 1)^D local nodes: elementBase(e) + the local
  // offset, wrapped along periodic axes for the last element's far nodes.
  void elementNodes(Index e, Index* nodes) const;
  // elementProduct on planar local vectors (component c at c (N + 1)^D + l), what the loop uses.
  void planarElementProduct(const Real* x, Real* y, const Material& material) const;
  // The centre of element e.
  Vec<D> elementCentre(Index e) const;
  // y += sign * K x over every element (x read with its fixed unknowns as zero), fixed rows left alone;
  // OpenMP over the elements of one colour at a time (elementColour), bitwise thread-independent.
  void addStiffnessProduct(const Real* x, Real* y, Real sign) const;
  // y += sign * K_e x_e for element e; `gathered` and `product` hold D (N + 1)^D values each,
  // `nodes` (N + 1)^D.
  void addElementProduct(Index e, const Real* x, Real* y, Real sign, Real* gathered, Real* product,
                         Index* nodes) const;
  // The parity of the element's index along each axis, one bit per axis: elements of one colour
  // share no node.
  int elementColour(Index e) const;
  // Below this many elements the product runs on one thread (a parallel region costs more).
  static constexpr Index kParallelElements = 64;

  SpectralElementSettings<D> settings_;
  Nodes elements_{}, nodes_{};
  std::array<bool, D> periodic_{};               // per axis
  Index pointsPerElement_ = 0;                   // (N + 1)^D
  std::vector<Real> gllNodes_, gllWeights_;
  std::array<std::vector<Real>, D> axisCoordinates_;  // the global nodes' coordinates along each axis
  std::vector<Index> localOffsets_;              // local node l -> its global node minus the element's first
  std::vector<Real> derivative_;                 // (2 / h) D_ij = dl_j/dx at node i, row major (N + 1)^2
  std::vector<Real> pointWeights_;               // GLL weight product times the Jacobian (h / 2)^D per point
  std::array<std::vector<int>, D> lineIndex_;    // per axis and local point: its index along that axis
  std::vector<Eigen::MatrixXd> denseElements_;   // 2-D only: K_e per material, cached for the faster dense product
  std::vector<Material> materials_;
  std::vector<int> elementMaterial_;             // per element (empty: one material)
  Vector mass_, damping_, volume_;               // diagonals; volume_ per node (sum of w J)
  std::vector<char> fixed_;
  std::vector<Vector> loadVectors_;              // per traction: integral of T phi_i over its rectangle
  bool hasDamping_ = false;
};

extern template class SpectralElementElasticity<2>;
extern template class SpectralElementElasticity<3>;

}  // namespace mfwave
