// VeryWeakSphProblem does the set-up drivers used to wire by hand: the same operator, dashpots and
// loads as the pieces assembled directly, prescribed faces with their values, and the combinations
// the method refuses.

#include "core/Error.hpp"
#include "kernels/KernelFactory.hpp"
#include "methods/very_weak_sph/PatchLoad.hpp"
#include "methods/very_weak_sph/TransmittingBoundary.hpp"
#include "methods/very_weak_sph/VeryWeakSph.hpp"
#include "methods/very_weak_sph/VeryWeakSphProblem.hpp"
#include "neighbours/CellList.hpp"
#include "particles/BoxFace.hpp"
#include "particles/GhostLayers.hpp"
#include "particles/Lattice.hpp"

#include <gtest/gtest.h>

namespace mfwave {
namespace {

constexpr Real kDx = 0.25;
const Vec2 kLower(0, 0), kUpper(2, 1.5);
const Material kMaterial = Material::fromLame(2.0, 1.0, 1.3);

ParticleSet<2> plateWithGhosts() {
  ParticleSet<2> particles = makeLattice<2>(kLower, kUpper, kDx);
  addGhostLayers<2>(particles, kLower, kUpper, kDx, 2, allFaces(2));
  return particles;
}

VeryWeakSphProblemSettings<2> settingsFor(VeryWeakSphVariant variant) {
  VeryWeakSphProblemSettings<2> s;
  s.options.material = kMaterial;
  s.options.variant = variant;
  s.smoothingLength = 1.2 * kDx;
  s.lower = kLower;
  s.upper = kUpper;
  s.spacing = kDx;
  return s;
}

Real difference(const SparseMatrix& a, const SparseMatrix& b) { return SparseMatrix(a - b).norm(); }

// The published variant with dashpots on +x and a triangle-shaped patch load on +y, through the
// problem and through the method's own functions: identical matrices and loads.
TEST(VeryWeakSphProblem, MatchesTheSetUpWiredByHand) {
  const ParticleSet<2> particles = plateWithGhosts();
  const TimeFunction history = TimeFunction::triangle(0, 1, 1);
  VeryWeakSphProblemSettings<2> settings = settingsFor(VeryWeakSphVariant::Published);
  settings.transmittingFaces = faceBit(BoxFace::PlusX);
  settings.dashpotLumping = DashpotLumping::Consistent;
  settings.patches.push_back({static_cast<int>(BoxFace::PlusY), Vec2(1, 1.5), Vec2(0.5, 0), Vec2(0, -2), &history});
  VeryWeakSphProblem<2> problem(particles, settings);

  const auto kernel = makeKernel("cubic_spline", 2, 1.2 * kDx);
  const NeighbourList neighbours =
      buildNeighbourList(CellList<2>(particles, kernel->supportRadius()), particles.physicalCount());
  VeryWeakSphOptions options = settings.options;
  VeryWeakSph<2> method = assembleVeryWeakSph<2>(particles, neighbours, *kernel, options);
  EXPECT_EQ(difference(problem.sparseSystem().stiffness(), method.system.stiffness()), 0.0);
  EXPECT_EQ(difference(problem.sparseSystem().mass(), method.system.mass()), 0.0);
  const SparseMatrix damping = assembleTransmittingDamping<2>(particles, neighbours, *kernel, method.data.facets,
                                                              kMaterial, faceBit(BoxFace::PlusX),
                                                              DashpotLumping::Consistent);
  EXPECT_GT(damping.norm(), 0.0);
  EXPECT_EQ(difference(problem.sparseSystem().damping(), damping), 0.0);
  const std::vector<Real> weights = patchLoadWeights<2>(particles, static_cast<int>(BoxFace::PlusY), Vec2(1, 1.5),
                                                        Vec2(0.5, 0), kDx, kLower, kUpper);
  const Vector expected =
      0.5 * (method.data.tractionMatrix *
             patchFacetTractions<2>(method.data.facets, static_cast<int>(BoxFace::PlusY), weights, Vec2(0, -2)));
  Vector f = Vector::Zero(problem.system().size());
  problem.system().force(0.5, f);
  EXPECT_GT(expected.norm(), 0.0);
  EXPECT_LE((f - expected).norm(), 1e-15 * expected.norm());
  // K is not kept twice unless asked; nothing the settings did not ask for is built
  EXPECT_EQ(problem.data().operatorMatrix.nonZeros(), 0);
  EXPECT_EQ(problem.smoothing(), nullptr);
  EXPECT_EQ(problem.deconvolution(), nullptr);
  EXPECT_TRUE(problem.prescribedDofs().empty());
  EXPECT_GT(problem.operatorMiB(), 0.0);
}

// A fixed face and a moving one: every component of their particles, in face order, at the
// values of eq. (30); the rest state starts at the values of t = 0.
TEST(VeryWeakSphProblem, PrescribesEveryComponentOfTheNamedFaces) {
  const ParticleSet<2> particles = makeLattice<2>(kLower, kUpper, kDx);
  const TimeFunction ramp = TimeFunction::ramp(0, 2, 1);
  VeryWeakSphProblemSettings<2> settings = settingsFor(VeryWeakSphVariant::Galerkin);
  settings.prescribed.push_back({faceBit(BoxFace::MinusX), Vec2::Zero(), nullptr});
  settings.prescribed.push_back({faceBit(BoxFace::PlusX), Vec2(0.1, -0.3), &ramp});
  VeryWeakSphProblem<2> problem(particles, settings);
  const Index perFace = 7;  // 1.5 / 0.25 + 1 particles on each x face
  ASSERT_EQ(problem.prescribedDofs().size(), static_cast<std::size_t>(2 * 2 * perFace));
  Vector g(static_cast<Index>(problem.prescribedDofs().size()));
  problem.prescribedValues(1.0, g);  // ramp at half its rise
  for (Index i = 0; i < 2 * perFace; ++i) EXPECT_EQ(g[i], 0.0);
  for (Index i = 2 * perFace; i < g.size(); i += 2) {
    EXPECT_DOUBLE_EQ(g[i], 0.05);
    EXPECT_DOUBLE_EQ(g[i + 1], -0.15);
  }
  for (Index dof : problem.prescribedDofs()) {
    const Real x = particles.position(dof / 2)[0];
    EXPECT_TRUE(x == kLower[0] || x == kUpper[0]) << "dof " << dof;
  }
  EXPECT_EQ(problem.initialDisplacement().norm(), 0.0);  // the ramp starts at 0
}

// The galerkin variant's patch load is the exact integral of its tent kernel: the nodal forces add
// up to the traction times the patch length.
TEST(VeryWeakSphProblem, GalerkinPatchLoadCarriesTheWholeTraction) {
  const ParticleSet<2> particles = makeLattice<2>(kLower, kUpper, kDx);
  const TimeFunction constant = TimeFunction::constant(1);
  VeryWeakSphProblemSettings<2> settings = settingsFor(VeryWeakSphVariant::Galerkin);
  settings.patches.push_back({static_cast<int>(BoxFace::PlusY), Vec2(1, 1.5), Vec2(0.4, 0), Vec2(0.5, -2), &constant});
  VeryWeakSphProblem<2> problem(particles, settings);
  Vector f = Vector::Zero(problem.system().size());
  problem.system().force(3.0, f);
  Real fx = 0, fy = 0;
  for (Index a = 0; a < particles.physicalCount(); ++a) {
    fx += f[2 * a];
    fy += f[2 * a + 1];
  }
  EXPECT_NEAR(fx, 0.5 * 0.8, 1e-12);
  EXPECT_NEAR(fy, -2 * 0.8, 1e-12);
}

TEST(VeryWeakSphProblem, RefusesWhatTheGalerkinVariantCannotDo) {
  const ParticleSet<2> particles = makeLattice<2>(kLower, kUpper, kDx);
  VeryWeakSphProblemSettings<2> settings = settingsFor(VeryWeakSphVariant::Galerkin);
  settings.deconvolution = true;
  try {
    VeryWeakSphProblem<2> problem(particles, settings);
    FAIL() << "deconvolution accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "method.deconvolution");
  }
  settings.deconvolution = false;
  settings.smoothingRate = 0.5;
  try {
    VeryWeakSphProblem<2> problem(particles, settings);
    FAIL() << "smoothing accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "method.smoothing_rate");
  }
  // the published variant takes both
  settings.options.variant = VeryWeakSphVariant::Published;
  settings.deconvolution = true;
  VeryWeakSphProblem<2> published(particles, settings);
  EXPECT_NE(published.smoothing(), nullptr);
  EXPECT_NE(published.deconvolution(), nullptr);
}

}  // namespace
}  // namespace mfwave
