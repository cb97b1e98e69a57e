#pragma once
// Plane-strain isotropic elasticity by the spectral-element method (SEM, as in SPECFEM2D:
// Komatitsch & Vilotte 1998, Komatitsch & Tromp 1999): a structured mesh of equal square elements
// covering an axis-aligned rectangle, Gauss-Lobatto-Legendre (GLL) nodes of order N in each
// direction, the tensor-product Lagrange basis on them and GLL quadrature. Because the quadrature
// points are the interpolation nodes, M is diagonal (lumped) without any lumping step, and an
// explicit central difference needs no solve.
//
//   unknowns      two displacement components per global GLL node, interleaved (u[2 p + c]), nodes
//                 numbered row by row (p = j * nodesX + i), as the lattice systems lay them out
//   stiffness     ONE element matrix K_e (every element is the same square with the same material),
//                 K_e = sum over GLL points of B^T D B w J; K u is matrix-free: per element gather,
//                 multiply by K_e, scatter-add, elements in a fixed order (bitwise reproducible)
//   faces         free (natural), fixed (u = 0: those unknowns are masked out of K, f and the
//                 acceleration, so K stays symmetric), absorbing (Lysmer & Kuhlemeyer 1969
//                 dashpots: C diagonal, rho c_p on the normal and rho c_s on the tangential
//                 component, times the node's GLL weight times the edge Jacobian h / 2)
//   loads         tractions T(x) f(t) on a segment |x - centre| < halfWidth of a face, integrated
//                 against each basis function exactly (GLL on the face's element edges when the
//                 segment's ends are element boundaries; Gauss-Legendre on the loaded part of an
//                 edge when an end falls inside an element)

#include "core/Material.hpp"
#include "particles/ParticleSet.hpp"
#include "systems/LinearOperatorSystem.hpp"

#include <array>
#include <functional>
#include <vector>

namespace mfwave {

enum class SpectralElementFace { Free, Fixed, Absorbing };

struct SpectralElementTraction {
  int face = 3;           // BoxFace number (0 -x, 1 +x, 2 -y, 3 +y)
  Real centre = 0;        // along the face
  Real halfWidth = 0;     // the loaded segment |x - centre| < halfWidth
  Vec2 traction = Vec2::Zero();  // Pa, constant on the segment
  std::function<Real(Real)> history;  // f(t)
};

struct SpectralElementSettings {
  Vec2 lower = Vec2::Zero(), upper = Vec2::Zero();
  Real elementSize = 1;
  int order = 4;  // N: N + 1 GLL nodes per element edge
  Material material = Material::fromLame(1, 1, 1);
  std::array<SpectralElementFace, 4> faces{SpectralElementFace::Free, SpectralElementFace::Free,
                                           SpectralElementFace::Free, SpectralElementFace::Free};
  std::vector<SpectralElementTraction> tractions;
};

class SpectralElementElasticity : public LinearOperatorSystem {
 public:
  // Throws InputError("order") outside 1..8, InputError("elementSize") when the rectangle is not a
  // whole number of elements, InputError("traction") for a segment outside its face, of no width,
  // or a traction without history.
  explicit SpectralElementElasticity(SpectralElementSettings settings);

  Index size() const override { return 2 * nodeCount(); }
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

  Index nodeCount() const { return nodes_[0] * nodes_[1]; }
  std::array<Index, 2> nodesPerAxis() const { return nodes_; }
  std::array<Index, 2> elementsPerAxis() const { return elements_; }
  Vec2 nodePosition(Index node) const;
  // The global node at x, or -1 when no node is within 1e-9 element sizes of it.
  Index nodeAt(const Vec2& x) const;
  // The GLL nodes as particles: volume = the lumped mass over rho, face bits of the box faces a
  // node lies on (what the probes and the Lamb scores read).
  ParticleSet<2> nodeParticles() const;
  const Eigen::MatrixXd& elementStiffness() const { return elementStiffness_; }
  const Vector& dampingDiagonal() const { return damping_; }
  // 1 for the unknowns a fixed face holds at zero.
  const std::vector<char>& fixedDofs() const { return fixed_; }
  const SpectralElementSettings& settings() const { return settings_; }
  // The GLL points of the reference element [-1, 1].
  const std::vector<Real>& referenceNodes() const { return gllNodes_; }

  // r = f(t) - K u - C v on every unknown (zero on fixed ones).
  void residual(Real t, const Real* u, const Real* v, Real* r) const;

 private:
  Index globalNode(Index ex, Index ey, int a, int b) const {
    return (ey * settings_.order + b) * nodes_[0] + ex * settings_.order + a;
  }
  void buildElementStiffness();
  void buildMassAndDamping();
  void buildLoads();
  // y += sign * K x over every element (x read with its fixed unknowns as zero), fixed rows left alone.
  void addStiffnessProduct(const Real* x, Real* y, Real sign) const;

  SpectralElementSettings settings_;
  std::array<Index, 2> elements_{0, 0}, nodes_{0, 0};
  std::vector<Real> gllNodes_, gllWeights_;
  std::array<std::vector<Real>, 2> axisCoordinates_;  // the global nodes' coordinates along each axis
  std::vector<Index> localOffsets_;      // local node b (N + 1) + a -> b nodesX + a
  Eigen::MatrixXd elementStiffness_;     // 2 (N + 1)^2 square, local dof 2 (b (N + 1) + a) + c
  Vector mass_, damping_;                // diagonals
  std::vector<char> fixed_;
  std::vector<Vector> loadVectors_;      // per traction: integral of T phi_i over its segment
  bool hasDamping_ = false;
};

}  // namespace mfwave
