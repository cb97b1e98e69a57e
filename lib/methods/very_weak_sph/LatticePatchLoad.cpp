#include "methods/very_weak_sph/LatticePatchLoad.hpp"

#include "methods/very_weak_sph/PatchLoad.hpp"
#include "particles/BoxFace.hpp"
#include "particles/Lattice.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <vector>

namespace mfwave {

namespace {

using Range = std::array<Index, 2>;  // nodes [first, end) along one axis

// Along every axis, the nodes of the loaded face's layer whose weight can be nonzero: within two
// spacings of the rectangle (a tent reaches one spacing, a cell half of one). At least one node, so
// that the weights' own checks of the patch run whatever it holds.
template <int D>
std::array<Range, D> loadedNodes(const VeryWeakSphProblemSettings<D>& settings, const PatchTraction<D>& patch,
                                 const std::array<Index, D>& nodes) {
  std::array<Range, D> range{};
  for (Range& r : range) r = {0, 1};
  if (patch.face < 0 || patch.face >= 2 * D) return range;  // the weights name the face
  const int normal = faceAxis(patch.face);
  for (int a = 0; a < D; ++a) {
    const auto s = static_cast<std::size_t>(a);
    const auto n = static_cast<Real>(nodes[s]);
    if (a == normal) {
      const Index layer = patch.face % 2 == 0 ? 0 : nodes[s] - 1;
      range[s] = {layer, layer + 1};
      continue;
    }
    const Real lo = (patch.centre[a] - patch.halfWidths[a] - settings.lower[a]) / settings.spacing - 2;
    const Real hi = (patch.centre[a] + patch.halfWidths[a] - settings.lower[a]) / settings.spacing + 2;
    if (!std::isfinite(lo) || !std::isfinite(hi)) continue;  // refused by the weights
    const auto first = static_cast<Index>(std::clamp(std::floor(lo), Real(0), n - 1));
    const auto end = static_cast<Index>(std::clamp(std::ceil(hi) + 1, static_cast<Real>(first + 1), n));
    range[s] = {first, end};
  }
  return range;
}

template <int D>
std::array<Range, D> widened(const std::array<Range, D>& range, Index by, const std::array<Index, D>& nodes) {
  std::array<Range, D> out{};
  for (std::size_t s = 0; s < static_cast<std::size_t>(D); ++s)
    out[s] = {std::max<Index>(0, range[s][0] - by), std::min(nodes[s], range[s][1] + by)};
  return out;
}

// Calls f(node) for every node of the box, x fastest (ascending lattice numbers).
template <int D, class Function>
void forEachNode(const std::array<Range, D>& box, Function&& f) {
  std::array<Index, D> node{};
  for (std::size_t s = 0; s < static_cast<std::size_t>(D); ++s) node[s] = box[s][0];
  while (true) {
    f(node);
    std::size_t s = 0;
    for (; s < static_cast<std::size_t>(D); ++s) {
      if (++node[s] < box[s][1]) break;
      node[s] = box[s][0];
    }
    if (s == static_cast<std::size_t>(D)) return;
  }
}

template <int D>
Index numberIn(const std::array<Range, D>& box, const std::array<Index, D>& node) {
  Index number = 0, stride = 1;
  for (std::size_t s = 0; s < static_cast<std::size_t>(D); ++s) {
    number += stride * (node[s] - box[s][0]);
    stride *= box[s][1] - box[s][0];
  }
  return number;
}

template <int D>
Index numberOn(const std::array<Index, D>& nodes, const std::array<Index, D>& node) {
  std::array<Range, D> whole{};
  for (std::size_t s = 0; s < static_cast<std::size_t>(D); ++s) whole[s] = {0, nodes[s]};
  return numberIn<D>(whole, node);
}

// The largest |offset| of any entry along any axis: how far a row reaches.
template <int D>
Index reachOf(const LatticeStencils<D>& stencils) {
  Index reach = 0;
  for (Index e = 0; e < stencils.entryCount(); ++e)
    for (Index o : stencils.offset(e)) reach = std::max(reach, static_cast<Index>(std::abs(o)));
  return reach;
}

}  // namespace

template <int D>
SparseLoad latticePatchLoad(const VeryWeakSphProblemSettings<D>& settings, const PatchTraction<D>& patch,
                            const std::array<Index, D>& nodes, const LatticeStencils<D>* faceStencils) {
  // The loaded face's nodes near the rectangle, with the positions and face tags of the whole lattice.
  const std::array<Range, D> loaded = loadedNodes<D>(settings, patch, nodes);
  std::array<Index, D> first{}, end{};
  for (std::size_t s = 0; s < static_cast<std::size_t>(D); ++s) {
    first[s] = loaded[s][0];
    end[s] = loaded[s][1];
  }
  const ParticleSet<D> block = makeLattice<D>(settings.lower, settings.upper, settings.spacing, first, end);
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
  const Index reach = reachOf<D>(g);
  const std::array<Range, D> rows = widened<D>(loaded, reach, nodes);
  const std::array<Range, D> read = widened<D>(loaded, 2 * reach, nodes);
  std::array<Index, D> readNodes{};
  Index readCount = 1;
  for (std::size_t s = 0; s < static_cast<std::size_t>(D); ++s) {
    readNodes[s] = read[s][1] - read[s][0];
    readCount *= readNodes[s];
  }
  std::vector<Real> nodal(static_cast<std::size_t>(D * readCount), 0.0);
  Index b = 0;
  forEachNode<D>(loaded, [&](const std::array<Index, D>& node) {
    const Real w = weights[static_cast<std::size_t>(b++)];
    for (int c = 0; c < D; ++c) nodal[static_cast<std::size_t>(D * numberIn<D>(read, node) + c)] = w * patch.traction[c];
  });
  const std::vector<Index> flat = g.flatOffsets(readNodes);
  forEachNode<D>(rows, [&](const std::array<Index, D>& node) {
    Real out[D];
    g.rowProductAt(g.types().typeOf(node), nodal.data() + D * numberIn<D>(read, node), flat.data(), out);
    for (int c = 0; c < D; ++c)
      if (out[c] != 0) {
        load.dofs.push_back(D * numberOn<D>(nodes, node) + c);
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
