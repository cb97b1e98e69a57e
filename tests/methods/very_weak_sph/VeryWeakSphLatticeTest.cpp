// The lattice storage of the very weak SPH (VeryWeakSphLattice, LatticeSecondOrderSystem) against
// the assembled sparse matrices it replaces: on the same lattice both give the same acceleration,
// the same dashpot solve of central difference (eq. (32), with prescribed dofs), the same loads and
// energies and the same smoothing filter to 1e-12 relative, in 1-, 2- and 3-D, for every variant and
// every boundary kind the lattice storage runs; what it cannot run is refused by name.

#include "core/Error.hpp"
#include "core/TimeFunction.hpp"
#include "methods/very_weak_sph/VeryWeakSphLattice.hpp"
#include "methods/very_weak_sph/VeryWeakSphProblem.hpp"
#include "particles/BoxFace.hpp"
#include "particles/GhostLayers.hpp"
#include "particles/Lattice.hpp"

#include "support/RandomVector.hpp"

#include <gtest/gtest.h>

#include <random>
#include <string>

namespace mfwave {
namespace {

const Material kLatticeMaterial = Material::fromLame(2.0, 1.0, 1.3);

template <int D>
struct Box {
  Vec<D> lower, upper;
  Real dx;
};

// Boxes longer than the compact lattices of the deepest variant, and not cubes (axis mix-ups show).
template <int D>
Box<D> boxFor(VeryWeakSphVariant variant);
template <>
Box<1> boxFor<1>(VeryWeakSphVariant) {
  return {Vec<1>(-1.0), Vec<1>(5.0), 0.25};
}
template <>
Box<2> boxFor<2>(VeryWeakSphVariant) {
  return {Vec2(0, -1), Vec2(5.5, 3.5), 0.25};
}
template <>
Box<3> boxFor<3>(VeryWeakSphVariant variant) {
  if (variant == VeryWeakSphVariant::Galerkin) return {Vec3(0, 0, -2), Vec3(2.25, 2.0, 0), 0.25};
  return {Vec3(0, 0, -3.5), Vec3(3.75, 3.5, 0), 0.25};
}

template <int D>
ParticleSet<D> particlesOn(const Box<D>& box) {
  ParticleSet<D> particles = makeLattice<D>(box.lower, box.upper, box.dx);
  addGhostLayers<D>(particles, box.lower, box.upper, box.dx, 2, allFaces(D));
  return particles;
}

template <int D>
VeryWeakSphProblemSettings<D> settingsOn(const Box<D>& box, VeryWeakSphVariant variant) {
  VeryWeakSphProblemSettings<D> s;
  s.options.material = kLatticeMaterial;
  s.options.variant = variant;
  s.smoothingLength = 1.1 * box.dx;
  s.lower = box.lower;
  s.upper = box.upper;
  s.spacing = box.dx;
  s.ghostLayers = 2;
  s.ghostFaces = allFaces(D);
  return s;
}

using test::randomVector;

Real relative(const Vector& a, const Vector& b) {
  const Real scale = b.cwiseAbs().maxCoeff();
  return (a - b).cwiseAbs().maxCoeff() / (scale > 0 ? scale : 1);
}

// Both storages of `settings`, compared on random states.
template <int D>
void expectSameSystem(const Box<D>& box, VeryWeakSphProblemSettings<D> settings, const std::string& what) {
  SCOPED_TRACE(what + " in " + std::to_string(D) + "-D");
  const ParticleSet<D> particles = particlesOn<D>(box);
  settings.storage = OperatorStorage::Sparse;
  VeryWeakSphProblem<D> sparse(particles, settings);
  settings.storage = OperatorStorage::Lattice;
  VeryWeakSphProblem<D> lattice(particles, settings);
  ASSERT_TRUE(lattice.latticeStorage());
  EXPECT_LE(lattice.latticeMismatch(), 1e-12);
  LinearOperatorSystem& a = sparse.system();
  LinearOperatorSystem& b = lattice.system();
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(a.hasDamping(), b.hasDamping());
  const Vector u = randomVector(a.size(), 1), v = randomVector(a.size(), 2);

  for (Real t : {0.3, 1.2}) {
    Vector accelerationA(a.size()), accelerationB(b.size());
    a.acceleration(t, u, v, accelerationA);
    b.acceleration(t, u, v, accelerationB);
    EXPECT_LE(relative(accelerationB, accelerationA), 1e-12) << "acceleration at t = " << t;
    Vector fA, fB;
    a.force(t, fA);
    b.force(t, fB);
    EXPECT_LE((fB - fA).cwiseAbs().maxCoeff(), 1e-12 * std::max<Real>(1, fA.cwiseAbs().maxCoeff())) << "f at t = " << t;
  }
  EXPECT_NEAR(b.kineticEnergy(v), a.kineticEnergy(v), 1e-12 * a.kineticEnergy(v));
  EXPECT_NEAR(b.strainEnergy(u), a.strainEnergy(u), 1e-12 * std::abs(a.strainEnergy(u)));
  EXPECT_NEAR(b.dampingPower(v), a.dampingPower(v), 1e-12 * std::max<Real>(1, std::abs(a.dampingPower(v))));
  EXPECT_LE(relative(b.lumpedMass(), a.lumpedMass()), 1e-14);
  EXPECT_LE(relative(b.stiffnessAbsoluteRowSums(), a.stiffnessAbsoluteRowSums()), 1e-12);
  Vector ka, kb;
  a.applyStiffness(u, ka);
  b.applyStiffness(u, kb);
  EXPECT_LE(relative(kb, ka), 1e-12);

  // the dashpot solve of central difference, with the prescribed dofs' accelerations imposed
  const std::vector<Index>& prescribed = sparse.prescribedDofs();
  EXPECT_EQ(lattice.prescribedDofs(), prescribed);
  const Vector known = randomVector(static_cast<Index>(prescribed.size()), 3);
  const auto solveA = a.centredDamping(0.05, prescribed);
  const auto solveB = b.centredDamping(0.05, prescribed);
  Vector stepA(a.size()), stepB(b.size());
  solveA->acceleration(0.7, u, v, known, stepA);
  solveB->acceleration(0.7, u, v, known, stepB);
  EXPECT_LE(relative(stepB, stepA), 1e-12) << "(M + dt/2 C) a = f - K u - C v";

  // the deconvolution (eq. (35)) at a few particles
  ASSERT_EQ(sparse.deconvolves(), lattice.deconvolves());
  if (sparse.deconvolves()) {
    const Index n = sparse.system().size() / D;
    const std::vector<Index> at{0, n / 2, n - 1, n / 3};
    const std::vector<int> components{0, D - 1, 0, D - 1};
    const ParticleMatrix rowsA = sparse.deconvolutionRows(at, components), rowsB = lattice.deconvolutionRows(at, components);
    const ParticleMatrix difference = rowsA - rowsB;
    EXPECT_LE(difference.coeffs().cwiseAbs().maxCoeff(), 1e-12) << "deconvolution";
    EXPECT_EQ(rowsB.nonZeros(), rowsA.nonZeros());
  }
  // the smoothing filter (eq. (33))
  ASSERT_EQ(static_cast<bool>(sparse.smoothing()), static_cast<bool>(lattice.smoothing()));
  if (sparse.smoothing()) {
    Vector filteredA = v, filteredB = v;
    sparse.smoothing()->apply(0.05, filteredA);
    lattice.smoothing()->apply(0.05, filteredB);
    EXPECT_LE(relative(filteredB, filteredA), 1e-12) << "smoothing";
  }

  // Set up from the lattice's description alone (a rank of a split run): the same system bit for bit.
  VeryWeakSphProblem<D> bare(settings);
  EXPECT_EQ(bare.prescribedDofs(), lattice.prescribedDofs());
  if (!lattice.prescribedDofs().empty()) {
    Vector gB(static_cast<Index>(lattice.prescribedDofs().size())), gC(gB.size());
    lattice.prescribedValues(1.2, gB);
    bare.prescribedValues(1.2, gC);
    EXPECT_EQ(gC, gB);
  }
  LinearOperatorSystem& c = bare.system();
  ASSERT_EQ(c.size(), b.size());
  for (Real t : {0.3, 1.2}) {
    Vector accelerationB(b.size()), accelerationC(c.size()), fB, fC;
    b.acceleration(t, u, v, accelerationB);
    c.acceleration(t, u, v, accelerationC);
    EXPECT_EQ(accelerationC, accelerationB) << "acceleration without particles at t = " << t;
    b.force(t, fB);
    c.force(t, fC);
    EXPECT_EQ(fC, fB) << "f without particles at t = " << t;
  }
  EXPECT_EQ(bare.operatorMiB(), lattice.operatorMiB());
  EXPECT_EQ(bare.meanStencilSize(), lattice.meanStencilSize());
  if (lattice.smoothing()) {
    Vector filteredB = v, filteredC = v;
    lattice.smoothing()->apply(0.05, filteredB);
    bare.smoothing()->apply(0.05, filteredC);
    EXPECT_EQ(filteredC, filteredB) << "smoothing without particles";
  }
  if (lattice.deconvolves()) {
    const std::vector<Index> at{0, c.size() / D - 1};
    const std::vector<int> components{0, D - 1};
    const ParticleMatrix difference = bare.deconvolutionRows(at, components) - lattice.deconvolutionRows(at, components);
    EXPECT_EQ(difference.norm(), 0) << "deconvolution without particles";
  }
}

template <int D>
void expectEveryBoundaryKind(VeryWeakSphVariant variant) {
  const Box<D> box = boxFor<D>(variant);
  const VeryWeakSphProblemSettings<D> plain = settingsOn<D>(box, variant);
  expectSameSystem<D>(box, plain, "free faces");

  const TimeFunction ramp = TimeFunction::ramp(0, 1);
  VeryWeakSphProblemSettings<D> loaded = plain;
  Vec<D> traction = Vec<D>::Zero();
  traction[0] = 0.4;
  traction[D - 1] = -1.5;
  loaded.faceTractions.push_back({faceBit(static_cast<BoxFace>(2 * D - 1)), traction, &ramp});
  loaded.faceTractions.push_back({faceBit(BoxFace::MinusX), Vec<D>::Constant(0.3), &ramp});
  expectSameSystem<D>(box, loaded, "face tractions");

  VeryWeakSphProblemSettings<D> clamped = plain;
  clamped.prescribed.push_back({faceBit(BoxFace::MinusX), Vec<D>::Zero(), nullptr});
  expectSameSystem<D>(box, clamped, "a fixed face");

  {
    VeryWeakSphProblemSettings<D> absorbing = loaded;
    std::uint8_t faces = 0;
    for (int f = 0; f < 2 * D - 1; ++f) faces |= faceBit(static_cast<BoxFace>(f));
    absorbing.transmittingFaces = faces;
    expectSameSystem<D>(box, absorbing, "transmitting faces");
    // dashpots and a moving face on the same particles: the per-particle solve keeps the coupling
    VeryWeakSphProblemSettings<D> moving = absorbing;
    moving.prescribed.push_back({faceBit(BoxFace::MinusX), Vec<D>::Constant(0.1), &ramp});
    expectSameSystem<D>(box, moving, "a moving face beside dashpots");
    if (variant == VeryWeakSphVariant::Published) {  // the dashpots through the traction sum couple particles
      absorbing.dashpotLumping = DashpotLumping::Consistent;
      expectSameSystem<D>(box, absorbing, "dashpots through the traction sum");
    }
  }
  if (variant != VeryWeakSphVariant::Galerkin) {  // the galerkin variant refuses filters
    VeryWeakSphProblemSettings<D> filtered = clamped;
    filtered.smoothingRate = 2.0;
    expectSameSystem<D>(box, filtered, "the smoothing filter");
    filtered.smoothingOrder = 2;
    expectSameSystem<D>(box, filtered, "the second-order smoothing filter");
    VeryWeakSphProblemSettings<D> sharpened = plain;
    sharpened.deconvolution = true;
    expectSameSystem<D>(box, sharpened, "the deconvolution");
  }
  {
    VeryWeakSphProblemSettings<D> patch = plain;
    const int top = 2 * D - 1;
    Vec<D> centre = 0.5 * (box.lower + box.upper), half = Vec<D>::Zero(), t = Vec<D>::Zero();
    centre[D - 1] = box.upper[D - 1];
    for (int a = 0; a + 1 < D; ++a) half[a] = 0.6;
    t[D - 1] = 1;
    patch.patches.push_back({top, centre, half, t, &ramp});
    // one over a corner of the face, clipped by two of its edges, and one off the lattice's nodes
    Vec<D> corner = box.lower, skew = centre;
    corner[D - 1] = box.upper[D - 1];
    for (int a = 0; a + 1 < D; ++a) skew[a] += 0.37 * box.dx;
    patch.patches.push_back({top, corner, half, 0.5 * t, &ramp});
    patch.patches.push_back({top, skew, 0.7 * half, Vec<D>::Constant(0.2), &ramp});
    if (D == 1) patch.patches.clear();  // a 1-D face is a point: whole-face tractions cover it
    patch.transmittingFaces = faceBit(BoxFace::MinusX);
    expectSameSystem<D>(box, patch, "a surface patch");
  }
}

TEST(VeryWeakSphLattice, GalerkinMatchesTheSparseMatricesIn1d2d3d) {
  expectEveryBoundaryKind<1>(VeryWeakSphVariant::Galerkin);
  expectEveryBoundaryKind<2>(VeryWeakSphVariant::Galerkin);
  expectEveryBoundaryKind<3>(VeryWeakSphVariant::Galerkin);
}

TEST(VeryWeakSphLattice, PublishedMatchesTheSparseMatricesIn1d2d3d) {
  expectEveryBoundaryKind<1>(VeryWeakSphVariant::Published);
  expectEveryBoundaryKind<2>(VeryWeakSphVariant::Published);
  expectEveryBoundaryKind<3>(VeryWeakSphVariant::Published);
}

TEST(VeryWeakSphLattice, ConsistentMatchesTheSparseMatricesIn1d2d3d) {
  expectEveryBoundaryKind<1>(VeryWeakSphVariant::Consistent);
  expectEveryBoundaryKind<2>(VeryWeakSphVariant::Consistent);
  expectEveryBoundaryKind<3>(VeryWeakSphVariant::Consistent);
}

// The galerkin rows change only at the face nodes (depth 1), the kernel variants' deeper.
TEST(VeryWeakSphLattice, FindsTheDepthWhereRowsStopChanging) {
  const Box<3> box = boxFor<3>(VeryWeakSphVariant::Galerkin);
  VeryWeakSphProblemSettings<3> s = settingsOn<3>(box, VeryWeakSphVariant::Galerkin);
  s.storage = OperatorStorage::Lattice;
  const VeryWeakSphProblem<3> galerkin(particlesOn<3>(box), s);
  EXPECT_EQ(galerkin.latticeDepth(), 1);
  EXPECT_EQ(galerkin.latticeSystem()->stiffness().typeCount(), 27);
  EXPECT_EQ(galerkin.neighbours().totalCount(), 0);  // no neighbour list
  const Box<3> deep = boxFor<3>(VeryWeakSphVariant::Published);
  VeryWeakSphProblemSettings<3> p = settingsOn<3>(deep, VeryWeakSphVariant::Published);
  p.storage = OperatorStorage::Lattice;
  const VeryWeakSphProblem<3> published(particlesOn<3>(deep), p);
  EXPECT_GE(published.latticeDepth(), 2);
  EXPECT_LE(published.latticeMismatch(), 1e-12);
}

TEST(VeryWeakSphLattice, RefusesParticlesOffItsLatticeAndHasNoMatrices) {
  const Box<2> box = boxFor<2>(VeryWeakSphVariant::Consistent);
  // particles that are not the settings' lattice
  VeryWeakSphProblemSettings<2> shifted = settingsOn<2>(box, VeryWeakSphVariant::Galerkin);
  shifted.storage = OperatorStorage::Lattice;
  shifted.lower[0] += box.dx;
  EXPECT_THROW(VeryWeakSphProblem<2>(particlesOn<2>(box), shifted), InputError);
  // the sparse matrices are not there to read
  VeryWeakSphProblemSettings<2> g = settingsOn<2>(box, VeryWeakSphVariant::Galerkin);
  g.storage = OperatorStorage::Lattice;
  VeryWeakSphProblem<2> problem(particlesOn<2>(box), g);
  EXPECT_THROW(problem.sparseSystem(), InputError);
  // without particles, only the lattice storage
  VeryWeakSphProblemSettings<2> sparse = settingsOn<2>(box, VeryWeakSphVariant::Galerkin);
  sparse.storage = OperatorStorage::Sparse;
  EXPECT_THROW(VeryWeakSphProblem<2>{sparse}, InputError);
}

}  // namespace
}  // namespace mfwave
