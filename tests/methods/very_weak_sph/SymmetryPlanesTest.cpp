// Symmetry planes of the very weak SPH's lattice storage (lattice/SymmetryFold.hpp): a block on one
// side of one or two mirror planes, loaded by a patch that reaches across them, is the whole
// (mirrored) block restricted to symmetric fields. For every variant in 2-D and 3-D, with
// transmitting far faces, the smoothing filter and the deconvolution where the variant has them:
// the acceleration, the dashpot solve, the load, the filter and the reported values at a probe on a
// plane are the whole block's on the modelled nodes to 1e-12, the energies are the whole solid's, and
// the normal displacement on a plane stays exactly zero. Both faces of an axis as planes, and the
// sparse storage with planes, are refused by name.

#include "core/Error.hpp"
#include "core/TimeFunction.hpp"
#include "methods/very_weak_sph/VeryWeakSphProblem.hpp"
#include "particles/BoxFace.hpp"
#include "particles/GhostLayers.hpp"
#include "particles/Lattice.hpp"

#include "support/RandomVector.hpp"

#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

namespace mfwave::symmetry_planes_test {
namespace {

const Material kMaterial = Material::fromLame(2.0, 1.0, 1.3);
const TimeFunction kHistory = TimeFunction::triangle(0.0, 1.0, 1.0);
constexpr Real kSpacing = 0.25;

// The modelled block: x >= 0 (and y >= 0 in 3-D), the loaded face the top (+y in 2-D, +z in 3-D).
template <int D>
struct Setup {
  Vec<D> lower, upper;           // the modelled block
  std::uint8_t symmetry = 0;     // its planes
  std::uint8_t transmitting = 0; // its far faces
  int loaded = 0;                // the loaded face
};

template <int D>
Setup<D> modelled();
template <>
Setup<2> modelled<2>() {
  return {Vec2(0, -1.5), Vec2(1.5, 0), faceBit(BoxFace::MinusX),
          static_cast<std::uint8_t>(faceBit(BoxFace::PlusX) | faceBit(BoxFace::MinusY)), 3};
}
template <>
Setup<3> modelled<3>() {
  return {Vec3(0, 0, -1.25), Vec3(1.25, 1.0, 0), static_cast<std::uint8_t>(faceBit(BoxFace::MinusX) | faceBit(BoxFace::MinusY)),
          static_cast<std::uint8_t>(faceBit(BoxFace::PlusX) | faceBit(BoxFace::PlusY) | faceBit(BoxFace::MinusZ)), 5};
}

template <int D>
bool isPlaneAxis(const Setup<D>& s, int axis) {
  return (s.symmetry & faceBit(2 * axis)) != 0;
}

// The patch as the modelled block's scene gives it: centred on the planes, reaching across them,
// with a tangential traction along x that the images reflect.
template <int D>
PatchTraction<D> patchOf(const Setup<D>& s) {
  PatchTraction<D> p;
  p.face = s.loaded;
  p.centre = Vec<D>::Zero();
  p.halfWidths = Vec<D>::Constant(0.5);
  p.halfWidths[D - 1] = 0;
  p.traction = Vec<D>::Zero();
  p.traction[0] = 0.3;
  p.traction[D - 1] = -1.0;
  p.history = &kHistory;
  return p;
}

template <int D>
VeryWeakSphProblemSettings<D> settingsOf(VeryWeakSphVariant variant, const Vec<D>& lower, const Vec<D>& upper) {
  VeryWeakSphProblemSettings<D> s;
  s.options.material = kMaterial;
  s.options.variant = variant;
  s.smoothingLength = 1.1 * kSpacing;
  s.lower = lower;
  s.upper = upper;
  s.spacing = kSpacing;
  s.storage = OperatorStorage::Lattice;
  if (variant != VeryWeakSphVariant::Galerkin) {
    s.ghostLayers = 2;
    s.ghostFaces = allFaces(D);
    s.smoothingRate = 0.5;
    s.deconvolution = true;
  }
  return s;
}

// The modelled block with its planes, and the whole block: mirrored across them, its far faces
// transmitting on both sides, the patch and its images (traction along x reversed across x = 0).
template <int D>
struct Pair {
  VeryWeakSphProblemSettings<D> part, whole;
};

template <int D>
Pair<D> pairOf(VeryWeakSphVariant variant) {
  const Setup<D> s = modelled<D>();
  Pair<D> pair;
  pair.part = settingsOf<D>(variant, s.lower, s.upper);
  pair.part.symmetryFaces = s.symmetry;
  pair.part.transmittingFaces = s.transmitting;
  if (variant != VeryWeakSphVariant::Galerkin) pair.part.ghostFaces = static_cast<std::uint8_t>(allFaces(D) & ~s.symmetry);
  pair.part.patches.push_back(patchOf<D>(s));

  Vec<D> lower = s.lower;
  for (int a = 0; a < D; ++a)
    if (isPlaneAxis(s, a)) lower[a] = -s.upper[a];
  pair.whole = settingsOf<D>(variant, lower, s.upper);
  std::uint8_t transmitting = s.transmitting;
  for (int a = 0; a < D; ++a)
    if (isPlaneAxis(s, a)) transmitting = static_cast<std::uint8_t>(transmitting | faceBit(2 * a));
  pair.whole.transmittingFaces = transmitting;
  // the whole patch as one image per quadrant: the part on each side, traction along x reflected
  const PatchTraction<D> full = patchOf<D>(s);
  const int planes = D == 3 ? 2 : 1;
  for (int set = 0; set < (1 << planes); ++set) {
    PatchTraction<D> image = full;
    for (int a = 0; a < planes; ++a) {
      const Real side = ((set >> a) & 1) ? -1 : 1;
      image.halfWidths[a] = full.halfWidths[a] / 2;
      image.centre[a] = side * full.halfWidths[a] / 2;
      if (side < 0) image.traction[a] = -image.traction[a];
    }
    pair.whole.patches.push_back(image);
  }
  return pair;
}

template <int D>
ParticleSet<D> particlesOf(const VeryWeakSphProblemSettings<D>& s) {
  ParticleSet<D> particles = makeLattice<D>(s.lower, s.upper, s.spacing);
  if (s.ghostLayers > 0) addGhostLayers<D>(particles, s.lower, s.upper, s.spacing, s.ghostLayers, s.ghostFaces);
  return particles;
}

// Lattice geometry of the pair: nodes per axis of the part, and the whole node of each part node.
template <int D>
struct Nodes {
  std::array<Index, D> part{}, whole{};
  Index partCount() const {
    Index n = 1;
    for (Index k : part) n *= k;
    return n;
  }
  Index wholeCount() const {
    Index n = 1;
    for (Index k : whole) n *= k;
    return n;
  }
};

template <int D>
Nodes<D> nodesOf(const Setup<D>& s) {
  Nodes<D> n;
  for (int a = 0; a < D; ++a) {
    const auto k = static_cast<std::size_t>(a);
    n.part[k] = static_cast<Index>(std::llround((s.upper[a] - s.lower[a]) / kSpacing)) + 1;
    n.whole[k] = isPlaneAxis(s, a) ? 2 * n.part[k] - 1 : n.part[k];
  }
  return n;
}

// The symmetric whole field of a field on the part (its normal components on the planes zeroed),
// and the whole field's values at the part's nodes.
template <int D>
Vector expand(const Setup<D>& s, const Nodes<D>& n, const Vector& part) {
  Vector whole(D * n.wholeCount());
  for (Index p = 0; p < n.wholeCount(); ++p) {
    Index rest = p, q = 0, stride = 1;
    std::array<bool, D> flipped{};
    for (int a = 0; a < D; ++a) {
      const auto k = static_cast<std::size_t>(a);
      Index i = rest % n.whole[k];
      rest /= n.whole[k];
      if (isPlaneAxis(s, a)) {
        i -= n.part[k] - 1;
        flipped[k] = i < 0;
        if (i < 0) i = -i;
      }
      q += i * stride;
      stride *= n.part[k];
    }
    for (int c = 0; c < D; ++c) whole[D * p + c] = (flipped[static_cast<std::size_t>(c)] ? -1 : 1) * part[D * q + c];
  }
  return whole;
}

template <int D>
Vector onPart(const Setup<D>& s, const Nodes<D>& n, const Vector& whole) {
  Vector part(D * n.partCount());
  for (Index q = 0; q < n.partCount(); ++q) {
    Index rest = q, p = 0, stride = 1;
    for (int a = 0; a < D; ++a) {
      const auto k = static_cast<std::size_t>(a);
      const Index i = rest % n.part[k];
      rest /= n.part[k];
      p += (isPlaneAxis(s, a) ? i + n.part[k] - 1 : i) * stride;
      stride *= n.whole[k];
    }
    part.template segment<D>(D * q) = whole.template segment<D>(D * p);
  }
  return part;
}

template <int D>
Vector symmetricField(const Setup<D>& s, const Nodes<D>& n, unsigned seed) {
  Vector u = test::randomVector(D * n.partCount(), seed);
  for (Index q = 0; q < n.partCount(); ++q) {
    Index rest = q;
    for (int a = 0; a < D; ++a) {
      const Index i = rest % n.part[static_cast<std::size_t>(a)];
      rest /= n.part[static_cast<std::size_t>(a)];
      if (isPlaneAxis(s, a) && i == 0) u[D * q + a] = 0;
    }
  }
  return u;
}

Real relative(const Vector& a, const Vector& b) {
  const Real scale = b.cwiseAbs().maxCoeff();
  return (a - b).cwiseAbs().maxCoeff() / (scale > 0 ? scale : 1);
}

template <int D>
void expectWholeOnPart(VeryWeakSphVariant variant, const std::string& name) {
  SCOPED_TRACE(name + " in " + std::to_string(D) + "-D");
  const Setup<D> s = modelled<D>();
  const Nodes<D> n = nodesOf<D>(s);
  const Pair<D> pair = pairOf<D>(variant);
  const ParticleSet<D> partParticles = particlesOf<D>(pair.part), wholeParticles = particlesOf<D>(pair.whole);
  VeryWeakSphProblem<D> part(partParticles, pair.part), whole(wholeParticles, pair.whole);
  ASSERT_TRUE(part.latticeStorage());
  EXPECT_LE(part.latticeMismatch(), 1e-12);
  LinearOperatorSystem& a = part.system();
  LinearOperatorSystem& b = whole.system();
  ASSERT_EQ(a.size(), D * n.partCount());
  ASSERT_EQ(b.size(), D * n.wholeCount());

  const Vector u = symmetricField<D>(s, n, 1), v = symmetricField<D>(s, n, 2);
  const Vector uWhole = expand<D>(s, n, u), vWhole = expand<D>(s, n, v);
  for (Real t : {0.3, 1.2}) {
    Vector accPart(a.size()), accWhole(b.size());
    a.acceleration(t, u, v, accPart);
    b.acceleration(t, uWhole, vWhole, accWhole);
    EXPECT_LE(relative(accPart, onPart<D>(s, n, accWhole)), 1e-12) << "acceleration at t = " << t;
  }
  // The load as the whole solid sees it: P^T f, f the whole block's (symmetric) load.
  Vector fPart, fWhole;
  a.force(0.7, fPart);
  b.force(0.7, fWhole);
  EXPECT_GT(fWhole.cwiseAbs().maxCoeff(), 0);
  EXPECT_NEAR(a.dot(fPart, u), b.dot(fWhole, uWhole), 1e-12 * fWhole.cwiseAbs().sum()) << "the load's work";
  // The whole solid's energies.
  EXPECT_NEAR(a.kineticEnergy(v), b.kineticEnergy(vWhole), 1e-12 * b.kineticEnergy(vWhole));
  EXPECT_NEAR(a.strainEnergy(u), b.strainEnergy(uWhole), 1e-12 * std::abs(b.strainEnergy(uWhole)));
  EXPECT_NEAR(a.dampingPower(v), b.dampingPower(vWhole), 1e-12 * std::abs(b.dampingPower(vWhole)));
  // The dashpot solve of central difference (eq. (32)).
  const auto solvePart = a.centredDamping(0.05, {});
  const auto solveWhole = b.centredDamping(0.05, {});
  Vector stepPart(a.size()), stepWhole(b.size());
  solvePart->acceleration(0.7, u, v, Vector(), stepPart);
  solveWhole->acceleration(0.7, uWhole, vWhole, Vector(), stepWhole);
  EXPECT_LE(relative(stepPart, onPart<D>(s, n, stepWhole)), 1e-12) << "(M + dt/2 C) a = f - K u - C v";
  // The normal displacement on a plane: its acceleration is exactly zero.
  for (Index q = 0; q < n.partCount(); ++q) {
    Index rest = q;
    for (int ax = 0; ax < D; ++ax) {
      const Index i = rest % n.part[static_cast<std::size_t>(ax)];
      rest /= n.part[static_cast<std::size_t>(ax)];
      if (isPlaneAxis(s, ax) && i == 0) {
        EXPECT_EQ(stepPart[D * q + ax], 0) << "node " << q;
      }
    }
  }

  if (variant == VeryWeakSphVariant::Galerkin) return;
  // The smoothing filter (eq. (33)) and the reported values at the load centre (eq. (35)).
  Vector filteredPart = v, filteredWhole = vWhole;
  part.smoothing()->apply(0.05, filteredPart);
  whole.smoothing()->apply(0.05, filteredWhole);
  EXPECT_LE(relative(filteredPart, onPart<D>(s, n, filteredWhole)), 1e-12) << "smoothing";
  // The load centre: (0, .., top) on the part, the middle of the top face on the whole block.
  Index centrePart = n.part[D - 1] - 1, centreWhole = n.whole[D - 1] - 1;
  for (int ax = D - 2; ax >= 0; --ax) {
    centrePart *= n.part[static_cast<std::size_t>(ax)];
    centreWhole = centreWhole * n.whole[static_cast<std::size_t>(ax)] + n.whole[static_cast<std::size_t>(ax)] / 2;
  }
  for (int c = 1; c < D; ++c) {
    const ParticleMatrix rowPart = part.deconvolutionRows({centrePart}, {c});
    const ParticleMatrix rowWhole = whole.deconvolutionRows({centreWhole}, {c});
    Vector componentPart(n.partCount()), componentWhole(n.wholeCount());
    for (Index q = 0; q < n.partCount(); ++q) componentPart[q] = u[D * q + c];
    for (Index p = 0; p < n.wholeCount(); ++p) componentWhole[p] = uWhole[D * p + c];
    const Real reportedPart = (rowPart * componentPart)[0], reportedWhole = (rowWhole * componentWhole)[0];
    EXPECT_NEAR(reportedPart, reportedWhole, 1e-12 * std::max<Real>(1, std::abs(reportedWhole))) << "component " << c;
  }
}

TEST(SymmetryPlanesTest, GalerkinIsTheWholeBlockOnSymmetricFields) {
  expectWholeOnPart<2>(VeryWeakSphVariant::Galerkin, "galerkin");
  expectWholeOnPart<3>(VeryWeakSphVariant::Galerkin, "galerkin");
}

TEST(SymmetryPlanesTest, KernelVariantsAreTheWholeBlockOnSymmetricFields) {
  expectWholeOnPart<2>(VeryWeakSphVariant::Consistent, "consistent");
  expectWholeOnPart<3>(VeryWeakSphVariant::Consistent, "consistent");
  expectWholeOnPart<2>(VeryWeakSphVariant::Published, "published");
  expectWholeOnPart<3>(VeryWeakSphVariant::Published, "published");
}

TEST(SymmetryPlanesTest, RefusesWhatIsNotAMirror) {
  Pair<2> pair = pairOf<2>(VeryWeakSphVariant::Galerkin);
  const ParticleSet<2> particles = particlesOf<2>(pair.part);
  VeryWeakSphProblemSettings<2> both = pair.part;
  both.symmetryFaces = static_cast<std::uint8_t>(faceBit(BoxFace::MinusX) | faceBit(BoxFace::PlusX));
  try {
    VeryWeakSphProblem<2> problem(particles, both);
    FAIL() << "both faces of x as planes";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "boundary");
    EXPECT_NE(std::string(e.what()).find("both faces of axis x"), std::string::npos) << e.what();
  }
  VeryWeakSphProblemSettings<2> sparse = pair.part;
  sparse.storage = OperatorStorage::Sparse;
  try {
    VeryWeakSphProblem<2> problem(particles, sparse);
    FAIL() << "planes on the sparse storage";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "method.operator");
  }
}

}  // namespace
}  // namespace mfwave::symmetry_planes_test
