#include "methods/very_weak_sph/LatticePatchLoad.hpp"

#include "lattice/Box.hpp"
#include "lattice/StencilReach.hpp"
#include "lattice/SymmetryFold.hpp"
#include "methods/very_weak_sph/PatchLoad.hpp"
#include "particles/BoxFace.hpp"
#include "particles/Lattice.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace mfwave {

namespace {

// The nodes of the loaded face's layer whose weight can be nonzero: within two spacings of the
// rectangle across the face (a tent reaches one spacing, a cell half of one). At least one node
// per axis, so that the weights' own checks of the patch run whatever it holds.
template <int D>
Box<D> loadedNodes(const VeryWeakSphProblemSettings<D>& settings, const PatchTraction<D>& patch,
                   const std::array<Index, D>& nodes) {
  Box<D> box;
  box.hi.fill(1);
  if (patch.face < 0 || patch.face >= 2 * D) return box;  // the weights name the face
  const int normal = faceAxis(patch.face);
  for (int a = 0; a < D; ++a) {
    const auto s = static_cast<std::size_t>(a);
    const auto n = static_cast<Real>(nodes[s]);
    if (a == normal) {
      box.lo[s] = patch.face % 2 == 0 ? 0 : nodes[s] - 1;
      box.hi[s] = box.lo[s] + 1;
      continue;
    }
    const Real lo = (patch.centre[a] - patch.halfWidths[a] - settings.lower[a]) / settings.spacing - 2;
    const Real hi = (patch.centre[a] + patch.halfWidths[a] - settings.lower[a]) / settings.spacing + 2;
    if (!std::isfinite(lo) || !std::isfinite(hi)) continue;  // refused by the weights
    box.lo[s] = static_cast<Index>(std::clamp(std::floor(lo), Real(0), n - 1));
    box.hi[s] = static_cast<Index>(std::clamp(std::ceil(hi) + 1, static_cast<Real>(box.lo[s] + 1), n));
  }
  return box;
}

// The box the weights clip the patch to: the modelled box, continued across its symmetry planes
// by its mirror image.
template <int D>
std::array<Vec<D>, 2> clipBox(const VeryWeakSphProblemSettings<D>& settings) {
  Vec<D> lower = settings.lower, upper = settings.upper;
  for (int a = 0; a < D; ++a) {
    if ((settings.symmetryFaces & faceBit(2 * a)) != 0) lower[a] -= settings.upper[a] - settings.lower[a];
    if ((settings.symmetryFaces & faceBit(2 * a + 1)) != 0) upper[a] += settings.upper[a] - settings.lower[a];
  }
  return {lower, upper};
}

// The patch as the modelled side sees it: clipped to that side of every symmetry plane, then with
// its mirror images (the part of the symmetric load across the planes, traction reflected), one
// copy per set of planes it is reflected across. Without symmetry planes: the patch itself.
// Throws InputError("load") for a patch wholly across a plane.
template <int D>
std::vector<PatchTraction<D>> symmetricCopies(const VeryWeakSphProblemSettings<D>& settings,
                                              const PatchTraction<D>& patch) {
  PatchTraction<D> clipped = patch;
  std::vector<int> axes;
  for (int a = 0; a < D; ++a) {
    const bool low = (settings.symmetryFaces & faceBit(2 * a)) != 0, high = (settings.symmetryFaces & faceBit(2 * a + 1)) != 0;
    if (!low && !high) continue;
    axes.push_back(a);
    Real lo = patch.centre[a] - patch.halfWidths[a], hi = patch.centre[a] + patch.halfWidths[a];
    if (low) lo = std::max(lo, settings.lower[a]);
    if (high) hi = std::min(hi, settings.upper[a]);
    if (!(hi >= lo))
      throw InputError("load", std::string("the surface patch lies wholly across the symmetry plane of axis ") +
                                   axisName(a) + "; give the part on the modelled side");
    clipped.centre[a] = (lo + hi) / 2;
    clipped.halfWidths[a] = (hi - lo) / 2;
  }
  std::vector<PatchTraction<D>> copies;
  for (unsigned set = 0; set < (1u << axes.size()); ++set) {
    PatchTraction<D> copy = clipped;
    for (std::size_t k = 0; k < axes.size(); ++k) {
      if (((set >> k) & 1u) == 0) continue;
      const int a = axes[k];
      const Real plane = (settings.symmetryFaces & faceBit(2 * a)) != 0 ? settings.lower[a] : settings.upper[a];
      copy.centre[a] = 2 * plane - clipped.centre[a];
      copy.traction[a] = -clipped.traction[a];
      if (!(clipped.halfWidths[a] > 0) && clipped.centre[a] == plane) copy.halfWidths[a] = -1;  // no image of a line
    }
    bool empty = false;
    for (int a = 0; a < D; ++a) empty = empty || copy.halfWidths[a] < 0;
    if (set == 0 || !empty) copies.push_back(copy);
  }
  return copies;
}

// The nodes of every copy's loaded box.
template <int D>
Box<D> loadedNodesOfAll(const VeryWeakSphProblemSettings<D>& settings, const std::vector<PatchTraction<D>>& copies,
                        const std::array<Index, D>& nodes) {
  Box<D> box = loadedNodes<D>(settings, copies[0], nodes);
  for (std::size_t k = 1; k < copies.size(); ++k) {
    const Box<D> other = loadedNodes<D>(settings, copies[k], nodes);
    for (std::size_t s = 0; s < static_cast<std::size_t>(D); ++s) {
      box.lo[s] = std::min(box.lo[s], other.lo[s]);
      box.hi[s] = std::max(box.hi[s], other.hi[s]);
    }
  }
  return box;
}

}  // namespace

template <int D>
SparseLoad latticePatchLoad(const VeryWeakSphProblemSettings<D>& settings, const PatchTraction<D>& patch,
                            const std::array<Index, D>& nodes, const LatticeStencils<D>* faceStencils) {
  // The loaded face's nodes near the rectangle (and its images across symmetry planes), with the
  // positions and face tags of the whole lattice.
  const std::vector<PatchTraction<D>> copies = symmetricCopies<D>(settings, patch);
  const std::array<Vec<D>, 2> clip = clipBox<D>(settings);
  const Box<D> loaded = loadedNodesOfAll<D>(settings, copies, nodes);
  const ParticleSet<D> block = makeLattice<D>(settings.lower, settings.upper, settings.spacing, loaded.lo, loaded.hi);
  const SymmetryFold<D> symmetry(nodes, settings.symmetryFaces);
  Box<D> whole;
  whole.hi = nodes;
  SparseLoad load{{}, {}, patch.history};

  if (settings.options.variant == VeryWeakSphVariant::Galerkin) {  // the exact int_patch W_a t (GalerkinLattice.hpp)
    Vector force = Vector::Zero(D * block.physicalCount());
    for (const PatchTraction<D>& copy : copies) {
      const std::vector<Real> weights = patchTentWeights<D>(block, copy.face, copy.centre, copy.halfWidths,
                                                            settings.spacing, clip[0], clip[1]);
      force += patchNodalForce<D>(weights, settings.spacing, copy.traction);
    }
    for (Index b = 0; b < block.physicalCount(); ++b) {
      const std::array<Index, D> node = whole.node(block.globalId[static_cast<std::size_t>(b)]);
      for (int c = 0; c < D; ++c)
        if (force[D * b + c] != 0 && !symmetry.inert(node, c)) {  // P^T f (SymmetryFold.hpp)
          load.dofs.push_back(D * block.globalId[static_cast<std::size_t>(b)] + c);
          load.values.push_back(symmetry.multiplicity(node) * force[D * b + c]);
        }
    }
    return load;
  }

  // The kernel variants: G (weight_b t), row by row over the rows that reach a loaded node, read
  // from a box holding every node those rows read. G carries the symmetry planes' restriction.
  std::vector<Real> weights(static_cast<std::size_t>(block.physicalCount()), 0.0);
  std::vector<Vec<D>> tractions(weights.size(), Vec<D>::Zero());
  for (const PatchTraction<D>& copy : copies) {
    const std::vector<Real> w = patchLoadWeights<D>(block, copy.face, copy.centre, copy.halfWidths,
                                                    settings.spacing, clip[0], clip[1]);
    for (std::size_t b = 0; b < w.size(); ++b) tractions[b] += w[b] * copy.traction;
  }
  const LatticeStencils<D>& g = *faceStencils;
  std::array<Index, D> reach = stencilReach(g), twice{};
  for (std::size_t s = 0; s < static_cast<std::size_t>(D); ++s) twice[s] = 2 * reach[s];
  const Box<D> rows = grown<D>(loaded, reach, nodes);
  const Box<D> read = grown<D>(loaded, twice, nodes);
  std::vector<Real> nodal(static_cast<std::size_t>(D * read.count()), 0.0);
  Index b = 0;
  loaded.forEachNode([&](const std::array<Index, D>& node) {
    const Vec<D>& t = tractions[static_cast<std::size_t>(b++)];
    for (int c = 0; c < D; ++c) nodal[static_cast<std::size_t>(D * read.localIndex(node) + c)] = t[c];
  });
  std::array<Index, D> readNodes{};
  for (int a = 0; a < D; ++a) readNodes[static_cast<std::size_t>(a)] = read.extent(a);
  const std::vector<Index> flat = g.flatOffsets(readNodes);
  rows.forEachNode([&](const std::array<Index, D>& node) {
    Real out[D];
    g.rowProductAt(g.types().typeOf(node), nodal.data() + D * read.localIndex(node), flat.data(), out);
    for (int c = 0; c < D; ++c)
      if (out[c] != 0) {
        load.dofs.push_back(D * whole.localIndex(node) + c);
        load.values.push_back(out[c]);
      }
  });
  return load;
}

template SparseLoad latticePatchLoad<1>(const VeryWeakSphProblemSettings<1>&, const PatchTraction<1>&,
                                        const std::array<Index, 1>&, const LatticeStencils<1>*);
template SparseLoad latticePatchLoad<2>(const VeryWeakSphProblemSettings<2>&, const PatchTraction<2>&,
                                        const std::array<Index, 2>&, const LatticeStencils<2>*);
template SparseLoad latticePatchLoad<3>(const VeryWeakSphProblemSettings<3>&, const PatchTraction<3>&,
                                        const std::array<Index, 3>&, const LatticeStencils<3>*);

}  // namespace mfwave
