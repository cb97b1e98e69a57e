#include "methods/very_weak_sph/VeryWeakSphLattice.hpp"

#include "core/Error.hpp"
#include "lattice/SymmetryFold.hpp"
#include "particles/GhostLayers.hpp"
#include "particles/Lattice.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace mfwave {
namespace {

constexpr Real kTolerance = 1e-12;

// The settings on the box of `nodes` from the same lower corner, without the loads (the face
// tractions are read off its traction matrix, patches are not per row type) and prescribed faces.
// With symmetry planes the box is the whole (mirrored) one of that modelled box (SymmetryFold.hpp):
// its far faces carry the modelled box's far faces' conditions, and the planes are interior.
template <int D>
VeryWeakSphProblemSettings<D> onBox(const VeryWeakSphProblemSettings<D>& settings, const std::array<Index, D>& nodes) {
  const SymmetryFold<D> fold(nodes, settings.symmetryFaces);
  const std::array<Index, D> shift = fold.wholeOriginShift();
  VeryWeakSphProblemSettings<D> s = settings;
  s.storage = OperatorStorage::Sparse;
  for (int a = 0; a < D; ++a) {
    const auto k = static_cast<std::size_t>(a);
    s.lower[a] = settings.lower[a] + static_cast<Real>(shift[k]) * settings.spacing;
    s.upper[a] = s.lower[a] + static_cast<Real>(fold.wholeNodes()[k] - 1) * settings.spacing;
  }
  s.transmittingFaces = mirroredFaceMask(settings.transmittingFaces, settings.symmetryFaces, D);
  s.ghostFaces = mirroredFaceMask(settings.ghostFaces, settings.symmetryFaces, D);
  s.symmetryFaces = 0;
  s.faceTractions.clear();
  s.patches.clear();
  s.prescribed.clear();
  s.keepOperatorMatrix = false;
  return s;
}

// An assembly on the whole box of onBox as the modelled lattice's operators: unchanged without
// symmetry planes, else their Galerkin restriction (forces) or fold (maps of the field).
template <int D>
struct OnModelled {
  SymmetryFold<D> fold;
  SparseMatrix operatorOf(const SparseMatrix& whole) const { return fold.active() ? fold.restrictOperator(whole) : whole; }
  SparseMatrix mapOf(const SparseMatrix& whole) const { return fold.active() ? fold.foldMap(whole) : whole; }
  Vector forceOf(const Vector& whole) const { return fold.active() ? fold.restrictForce(whole) : whole; }
};

template <int D>
ParticleSet<D> particlesOf(const VeryWeakSphProblemSettings<D>& s) {
  ParticleSet<D> particles = makeLattice<D>(s.lower, s.upper, s.spacing);
  if (s.ghostLayers > 0 && s.ghostFaces != 0)
    addGhostLayers<D>(particles, s.lower, s.upper, s.spacing, s.ghostLayers, s.ghostFaces);
  return particles;
}

// S of eq. (33) acting on every component of an interleaved field: S x I.
template <int D>
SparseMatrix onEveryComponent(const ParticleMatrix& s) {
  std::vector<Triplet> entries;
  entries.reserve(static_cast<std::size_t>(D * s.nonZeros()));
  for (int row = 0; row < s.outerSize(); ++row)
    for (ParticleMatrix::InnerIterator it(s, row); it; ++it)
      for (int c = 0; c < D; ++c)
        entries.emplace_back(static_cast<int>(D * it.row() + c), static_cast<int>(D * it.col() + c), it.value());
  SparseMatrix m(D * s.rows(), D * s.cols());
  m.setFromTriplets(entries.begin(), entries.end());
  return m;
}

// G_ab = T(a, facet of b on `face`): the traction matrix's columns of one face's facets, as a
// square node-to-node operator (zero columns for nodes off the face).
template <int D>
SparseMatrix faceTractionGather(const VeryWeakSphData<D>& data, int face, Index nodes) {
  std::vector<Index> facetOf(static_cast<std::size_t>(nodes), -1);  // node -> its facet on the face
  for (Index f = 0; f < data.facets.count(); ++f)
    if (data.facets.face[static_cast<std::size_t>(f)] == face)
      facetOf[static_cast<std::size_t>(data.facets.particle[static_cast<std::size_t>(f)])] = f;
  std::vector<Index> nodeOf(static_cast<std::size_t>(data.facets.count()), -1);
  for (Index b = 0; b < nodes; ++b)
    if (facetOf[static_cast<std::size_t>(b)] >= 0) nodeOf[static_cast<std::size_t>(facetOf[static_cast<std::size_t>(b)])] = b;
  std::vector<Triplet> entries;
  const SparseMatrix& t = data.tractionMatrix;
  for (int column = 0; column < t.outerSize(); ++column) {
    const Index b = nodeOf[static_cast<std::size_t>(column / D)];
    if (b < 0) continue;
    for (SparseMatrix::InnerIterator it(t, column); it; ++it)
      entries.emplace_back(it.row(), static_cast<int>(D * b + column % D), it.value());
  }
  SparseMatrix g(D * nodes, D * nodes);
  g.setFromTriplets(entries.begin(), entries.end());
  return g;
}

template <int D>
bool needsPatchFace(const VeryWeakSphProblemSettings<D>& settings, int face) {
  if (settings.options.variant == VeryWeakSphVariant::Galerkin) return false;  // its patch load is exact per node
  for (const PatchTraction<D>& patch : settings.patches)
    if (patch.face == face) return true;
  return false;
}

}  // namespace

template <int D>
std::array<Index, D> latticeNodesOf(const VeryWeakSphProblemSettings<D>& settings) {
  std::array<Index, D> nodes = latticeIntervals<D>(settings.lower, settings.upper, settings.spacing);
  for (Index& n : nodes) ++n;
  return nodes;
}

template <int D>
std::array<Index, D> checkedLatticeNodes(const ParticleSet<D>& particles, const VeryWeakSphProblemSettings<D>& settings) {
  const Real dx = settings.spacing;
  const std::array<Index, D> nodes = latticeNodesOf<D>(settings);
  Index count = 1;
  for (Index n : nodes) count *= n;
  if (particles.physicalCount() != count)
    throw InputError("method.operator", "the lattice storage needs the particles of the box lattice (" +
                                            std::to_string(count) + " nodes), got " +
                                            std::to_string(particles.physicalCount()) + " physical particles");
  const Real tolerance = 1e-6 * dx;
  for (Index p = 0; p < count; ++p) {
    Index rest = p;
    for (int a = 0; a < D; ++a) {
      const Index i = rest % nodes[static_cast<std::size_t>(a)];
      rest /= nodes[static_cast<std::size_t>(a)];
      const Real expected = settings.lower[a] + static_cast<Real>(i) * dx;
      if (std::abs(particles.coordinate(a)[static_cast<std::size_t>(p)] - expected) > tolerance)
        throw InputError("method.operator", "the lattice storage needs lattice particles in lattice order; particle " +
                                                std::to_string(p) + " is not at its node (axis " + std::to_string(a) + ")");
    }
  }
  return nodes;
}

template <int D>
VeryWeakSphStencils<D> veryWeakSphStencils(const VeryWeakSphProblemSettings<D>& settings,
                                           const std::array<Index, D>& nodes, Index maxDepth) {
  Real closest = std::numeric_limits<Real>::infinity();
  for (Index depth = 1; depth <= maxDepth; ++depth) {
    const LatticeRowTypes<D> types(nodes, depth);
    const VeryWeakSphProblemSettings<D> compactSettings = onBox<D>(settings, types.compactNodes());
    VeryWeakSphProblem<D> compact(particlesOf<D>(compactSettings), compactSettings);
    LinearSecondOrderSystem& system = compact.sparseSystem();
    const OnModelled<D> modelled{SymmetryFold<D>(types.compactNodes(), settings.symmetryFaces)};
    const auto compactWholeNodes = static_cast<Index>(system.mass().rows() / D);
    VeryWeakSphStencils<D> result;
    result.mass = LatticeStencils<D>(types, modelled.operatorOf(system.mass()));
    result.stiffness = LatticeStencils<D>(types, modelled.operatorOf(system.stiffness()));
    if (system.hasDamping()) result.damping = LatticeStencils<D>(types, modelled.operatorOf(system.damping()));
    if (compact.smoothing())
      result.smoothing = LatticeStencils<D>(types, modelled.mapOf(onEveryComponent<D>(compact.smoothing()->matrix())));
    if (compact.deconvolution())
      result.deconvolution = LatticeStencils<D>(types, modelled.mapOf(onEveryComponent<D>(*compact.deconvolution())));
    result.patchFaces.resize(2 * D);
    for (int face = 0; face < 2 * D; ++face)
      if (needsPatchFace<D>(settings, face))
        result.patchFaces[static_cast<std::size_t>(face)] = LatticeStencils<D>(
            types, modelled.operatorOf(faceTractionGather<D>(compact.data(), face, compactWholeNodes)));

    // The check: an assembly two nodes longer per axis (as far as the lattice goes) must be the
    // stencils' rows. When the compact box is the whole box there is nothing to check.
    if (types.compactNodes() != nodes) {
      std::array<Index, D> checkNodes{};
      for (int a = 0; a < D; ++a) {
        const auto s = static_cast<std::size_t>(a);
        checkNodes[s] = std::min(nodes[s], types.compactNodes()[s] + 2);
      }
      const LatticeRowTypes<D> checkTypes = types.on(checkNodes);
      const VeryWeakSphProblemSettings<D> checkSettings = onBox<D>(settings, checkNodes);
      VeryWeakSphProblem<D> check(particlesOf<D>(checkSettings), checkSettings);
      LinearSecondOrderSystem& checked = check.sparseSystem();
      const OnModelled<D> checkModelled{SymmetryFold<D>(checkNodes, settings.symmetryFaces)};
      const auto checkWholeNodes = static_cast<Index>(checked.mass().rows() / D);
      result.mismatch = std::max(result.stiffness.on(checkTypes).mismatch(checkModelled.operatorOf(checked.stiffness())),
                                 result.mass.on(checkTypes).mismatch(checkModelled.operatorOf(checked.mass())));
      if (compact.smoothing())
        result.mismatch = std::max(result.mismatch, result.smoothing.on(checkTypes).mismatch(checkModelled.mapOf(
                                                        onEveryComponent<D>(check.smoothing()->matrix()))));
      if (compact.deconvolution())
        result.mismatch = std::max(result.mismatch, result.deconvolution.on(checkTypes).mismatch(
                                                        checkModelled.mapOf(onEveryComponent<D>(*check.deconvolution()))));
      for (int face = 0; face < 2 * D; ++face)
        if (needsPatchFace<D>(settings, face))
          result.mismatch = std::max(result.mismatch,
                                     result.patchFaces[static_cast<std::size_t>(face)].on(checkTypes).mismatch(
                                         checkModelled.operatorOf(faceTractionGather<D>(check.data(), face, checkWholeNodes))));
      if (checked.hasDamping() != system.hasDamping()) result.mismatch = std::numeric_limits<Real>::infinity();
      else if (system.hasDamping())
        result.mismatch = std::max(result.mismatch,
                                   result.damping.on(checkTypes).mismatch(checkModelled.operatorOf(checked.damping())));
      if (!(result.mismatch <= kTolerance)) {
        closest = std::min(closest, result.mismatch);
        continue;
      }
    }

    // Face tractions at unit history, from the compact assembly's traction matrix.
    for (const FaceTraction<D>& traction : settings.faceTractions) {
      const Vector f = modelled.forceOf(faceTractionLoad<D>(
          compact.data(), mirroredFaceMask(traction.faces, settings.symmetryFaces, D), traction.traction));
      result.faceLoads.emplace_back(f.data(), f.data() + f.size());
    }
    return result;
  }
  throw InputError("method.operator", "the very weak SPH rows still change " + std::to_string(maxDepth) +
                                          " nodes from a face (closest mismatch " + std::to_string(closest) +
                                          "); use method.operator = \"sparse\"");
}

template std::array<Index, 1> latticeNodesOf<1>(const VeryWeakSphProblemSettings<1>&);
template std::array<Index, 2> latticeNodesOf<2>(const VeryWeakSphProblemSettings<2>&);
template std::array<Index, 3> latticeNodesOf<3>(const VeryWeakSphProblemSettings<3>&);
template std::array<Index, 1> checkedLatticeNodes<1>(const ParticleSet<1>&, const VeryWeakSphProblemSettings<1>&);
template std::array<Index, 2> checkedLatticeNodes<2>(const ParticleSet<2>&, const VeryWeakSphProblemSettings<2>&);
template std::array<Index, 3> checkedLatticeNodes<3>(const ParticleSet<3>&, const VeryWeakSphProblemSettings<3>&);
template VeryWeakSphStencils<1> veryWeakSphStencils<1>(const VeryWeakSphProblemSettings<1>&, const std::array<Index, 1>&, Index);
template VeryWeakSphStencils<2> veryWeakSphStencils<2>(const VeryWeakSphProblemSettings<2>&, const std::array<Index, 2>&, Index);
template VeryWeakSphStencils<3> veryWeakSphStencils<3>(const VeryWeakSphProblemSettings<3>&, const std::array<Index, 3>&, Index);

}  // namespace mfwave
