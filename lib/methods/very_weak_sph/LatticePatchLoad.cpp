#include "methods/very_weak_sph/LatticePatchLoad.hpp"

#include "lattice/Box.hpp"
#include "lattice/StencilReach.hpp"
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

}  // namespace

template <int D>
SparseLoad latticePatchLoad(const VeryWeakSphProblemSettings<D>& settings, const PatchTraction<D>& patch,
                            const std::array<Index, D>& nodes, const LatticeStencils<D>* faceStencils) {
  // The loaded face's nodes near the rectangle, with the positions and face tags of the whole lattice.
  const Box<D> loaded = loadedNodes<D>(settings, patch, nodes);
  const ParticleSet<D> block = makeLattice<D>(settings.lower, settings.upper, settings.spacing, loaded.lo, loaded.hi);
  SparseLoad load{{}, {}, patch.history};

  if (settings.options.variant == VeryWeakSphVariant::Galerkin) {  // the exact int_patch W_a t (GalerkinLattice.hpp)
    const std::vector<Real> weights = patchTentWeights<D>(block, patch.face, patch.centre, patch.halfWidths,
                                                          settings.spacing, settings.lower, settings.upper);
    const Vector force = patchNodalForce<D>(weights, settings.spacing, patch.traction);
    for (Index b = 0; b < block.physicalCount(); ++b)
      for (int c = 0; c < D; ++c)
        if (force[D * b + c] != 0) {
          load.dofs.push_back(D * block.globalId[static_cast<std::size_t>(b)] + c);
          load.values.push_back(force[D * b + c]);
        }
    return load;
  }

  // The kernel variants: G (weight_b t), row by row over the rows that reach a loaded node, read
  // from a box holding every node those rows read.
  const std::vector<Real> weights = patchLoadWeights<D>(block, patch.face, patch.centre, patch.halfWidths,
                                                        settings.spacing, settings.lower, settings.upper);
  const LatticeStencils<D>& g = *faceStencils;
  std::array<Index, D> reach = stencilReach(g), twice{};
  for (std::size_t s = 0; s < static_cast<std::size_t>(D); ++s) twice[s] = 2 * reach[s];
  const Box<D> rows = grown<D>(loaded, reach, nodes);
  const Box<D> read = grown<D>(loaded, twice, nodes);
  std::vector<Real> nodal(static_cast<std::size_t>(D * read.count()), 0.0);
  Index b = 0;
  loaded.forEachNode([&](const std::array<Index, D>& node) {
    const Real w = weights[static_cast<std::size_t>(b++)];
    for (int c = 0; c < D; ++c) nodal[static_cast<std::size_t>(D * read.localIndex(node) + c)] = w * patch.traction[c];
  });
  std::array<Index, D> readNodes{};
  for (int a = 0; a < D; ++a) readNodes[static_cast<std::size_t>(a)] = read.extent(a);
  const std::vector<Index> flat = g.flatOffsets(readNodes);
  Box<D> whole;
  whole.hi = nodes;
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
