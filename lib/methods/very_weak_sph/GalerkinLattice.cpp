#include "methods/very_weak_sph/GalerkinLattice.hpp"

#include "core/Error.hpp"
#include "particles/BoxFace.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace mfwave {
namespace {

// The 1-D integrals of the tents W_p, W_q on nodes 0..n with spacing h (only |p - q| <= 1 is
// non-zero). Each is a sum over the one or two intervals the two tents share.
struct Tent1d {
  Index n;
  Real h;
  // int W_p' W_q'
  Real stiffness(Index p, Index q) const {
    if (p == q) return (p == 0 || p == n ? 1 : 2) / h;
    return -1 / h;
  }
  // int W_p W_q
  Real mass(Index p, Index q) const {
    if (p == q) return (p == 0 || p == n ? 1 : 2) * h / 3;
    return h / 6;
  }
  // int W_p W_q'
  Real gradient(Index p, Index q) const {
    if (q == p + 1) return 0.5;
    if (q == p - 1) return -0.5;
    return (p == 0 ? -0.5 : 0) + (p == n ? 0.5 : 0);  // only the end intervals do not cancel
  }
  // int W_p
  Real lumped(Index p) const { return p == 0 || p == n ? h / 2 : h; }
};

// A_jl(a, b) = int d_j W_a d_l W_b as a product over axes (the kernel is a tensor product):
// the derivative factor where the axis is j or l, the mass factor elsewhere.
template <int D>
Real derivativeProduct(const std::array<Tent1d, D>& axes, const std::array<Index, D>& p,
                       const std::array<Index, D>& q, int j, int l) {
  Real value = 1;
  for (int ax = 0; ax < D; ++ax) {
    const Tent1d& t = axes[static_cast<std::size_t>(ax)];
    const Index pa = p[static_cast<std::size_t>(ax)], qa = q[static_cast<std::size_t>(ax)];
    if (ax == j && ax == l) value *= t.stiffness(pa, qa);
    else if (ax == j) value *= t.gradient(qa, pa);  // int W_p' W_q
    else if (ax == l) value *= t.gradient(pa, qa);
    else value *= t.mass(pa, qa);
  }
  return value;
}

template <int D>
Index linearNode(const std::array<Index, D>& node, const std::array<Index, D>& intervals) {
  Index index = 0, stride = 1;
  for (int ax = 0; ax < D; ++ax) {
    index += node[static_cast<std::size_t>(ax)] * stride;
    stride *= intervals[static_cast<std::size_t>(ax)] + 1;
  }
  return index;
}

// The lattice neighbours of node p (|q - p|_inf <= 1, p itself included) whose particles are
// listed in ascending particle order; with the dof order D b + k this is the sorted column order.
template <int D>
std::vector<Index> latticeNeighbours(const LatticeNodes<D>& lattice, const std::array<Index, D>& p) {
  std::vector<Index> out;
  int count = 1;
  for (int ax = 0; ax < D; ++ax) count *= 3;
  for (int c = 0; c < count; ++c) {
    std::array<Index, D> q = p;
    int code = c;
    bool inside = true;
    for (int ax = 0; ax < D; ++ax) {
      auto& qa = q[static_cast<std::size_t>(ax)];
      qa += code % 3 - 1;
      code /= 3;
      inside = inside && qa >= 0 && qa <= lattice.intervals[static_cast<std::size_t>(ax)];
    }
    if (inside) out.push_back(lattice.particleAt[static_cast<std::size_t>(linearNode<D>(q, lattice.intervals))]);
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

template <int D>
LatticeNodes<D> latticeNodes(const ParticleSet<D>& particles) {
  const Index n = particles.physicalCount();
  if (n == 0) throw InputError("method.variant", "the galerkin variant needs particles");
  LatticeNodes<D> lattice;
  lattice.spacing = std::pow(particles.volume[0], 1.0 / D);
  lattice.lower = particles.position(0);
  Vec<D> upper = lattice.lower;
  for (Index a = 1; a < n; ++a) {
    lattice.lower = lattice.lower.cwiseMin(particles.position(a));
    upper = upper.cwiseMax(particles.position(a));
  }
  const Real dx = lattice.spacing;
  Index nodes = 1;
  for (int ax = 0; ax < D; ++ax) {
    const Real intervals = (upper[ax] - lattice.lower[ax]) / dx;
    lattice.intervals[static_cast<std::size_t>(ax)] = static_cast<Index>(std::llround(intervals));
    if (lattice.intervals[static_cast<std::size_t>(ax)] < 1)
      throw InputError("method.variant", "the galerkin variant needs at least two particles along every axis");
    nodes *= lattice.intervals[static_cast<std::size_t>(ax)] + 1;
  }
  if (nodes != n)
    throw InputError("method.variant", "the galerkin variant needs the particles of a full box lattice (" +
                                           std::to_string(n) + " particles for " + std::to_string(nodes) +
                                           " lattice nodes)");
  lattice.node.resize(static_cast<std::size_t>(n));
  lattice.particleAt.assign(static_cast<std::size_t>(nodes), -1);
  for (Index a = 0; a < n; ++a) {
    const Vec<D> x = particles.position(a);
    std::array<Index, D>& node = lattice.node[static_cast<std::size_t>(a)];
    for (int ax = 0; ax < D; ++ax) {
      const Real s = (x[ax] - lattice.lower[ax]) / dx;
      node[static_cast<std::size_t>(ax)] = static_cast<Index>(std::llround(s));
      if (std::abs(s - static_cast<Real>(node[static_cast<std::size_t>(ax)])) > 1e-6)
        throw InputError("method.variant", "the galerkin variant needs lattice particles; particle " +
                                               std::to_string(a) + " is off the lattice of spacing " +
                                               std::to_string(dx));
    }
    Index& slot = lattice.particleAt[static_cast<std::size_t>(linearNode<D>(node, lattice.intervals))];
    if (slot >= 0)
      throw InputError("method.variant", "the galerkin variant needs one particle per lattice node; particles " +
                                             std::to_string(slot) + " and " + std::to_string(a) + " coincide");
    slot = a;
  }
  return lattice;
}

template <int D>
GalerkinLattice<D> assembleGalerkinLattice(const ParticleSet<D>& particles, const Material& material) {
  const LatticeNodes<D> lattice = latticeNodes(particles);
  const Index n = particles.physicalCount();
  std::array<Tent1d, D> axes;
  for (int ax = 0; ax < D; ++ax) axes[static_cast<std::size_t>(ax)] = {lattice.intervals[static_cast<std::size_t>(ax)], lattice.spacing};
  const Real lambda = material.lambda(), mu = material.mu();
  GalerkinLattice<D> out;

  // Lumped mass rho int W_a on every component.
  const int dofs = static_cast<int>(D * n);
  out.mass.resize(dofs, dofs);
  out.mass.reserve(Eigen::VectorXi::Constant(dofs, 1));
  for (Index a = 0; a < n; ++a) {
    Real weight = material.density();
    for (int ax = 0; ax < D; ++ax)
      weight *= axes[static_cast<std::size_t>(ax)].lumped(lattice.node[static_cast<std::size_t>(a)][static_cast<std::size_t>(ax)]);
    for (int i = 0; i < D; ++i) out.mass.insert(static_cast<int>(D * a + i), static_cast<int>(D * a + i)) = weight;
  }
  out.mass.makeCompressed();

  // Stiffness K_ab(i, k) = lambda A_ik + mu A_ki + mu delta_ik sum_j A_jj, A_jl = int d_j W_a d_l W_b
  // (C_ijkl = lambda d_ij d_kl + mu (d_ik d_jl + d_il d_jk)). K is symmetric, so column D a + i holds
  // row D a + i: each particle fills its own columns, in parallel, into precomputed slots.
  std::vector<int> columnStart(static_cast<std::size_t>(dofs) + 1, 0);
  for (Index a = 0; a < n; ++a) {
    int count = 1;  // lattice neighbours within one node per axis, the particle itself included
    for (int ax = 0; ax < D; ++ax) {
      const Index p = lattice.node[static_cast<std::size_t>(a)][static_cast<std::size_t>(ax)];
      count *= 1 + (p > 0 ? 1 : 0) + (p < lattice.intervals[static_cast<std::size_t>(ax)] ? 1 : 0);
    }
    for (int i = 0; i < D; ++i) columnStart[static_cast<std::size_t>(D * a + i) + 1] = D * count;
  }
  for (std::size_t c = 0; c < static_cast<std::size_t>(dofs); ++c) columnStart[c + 1] += columnStart[c];
  std::vector<int> rows(static_cast<std::size_t>(columnStart.back()));
  std::vector<Real> values(rows.size());
#pragma omp parallel for schedule(static)
  for (Index a = 0; a < n; ++a) {
    const std::array<Index, D>& p = lattice.node[static_cast<std::size_t>(a)];
    const std::vector<Index> neighbours = latticeNeighbours<D>(lattice, p);
    for (int i = 0; i < D; ++i) {
      auto slot = static_cast<std::size_t>(columnStart[static_cast<std::size_t>(D * a + i)]);
      for (const Index b : neighbours) {
        const std::array<Index, D>& q = lattice.node[static_cast<std::size_t>(b)];
        Real trace = 0;
        for (int j = 0; j < D; ++j) trace += derivativeProduct<D>(axes, p, q, j, j);
        for (int k = 0; k < D; ++k) {
          rows[slot] = static_cast<int>(D * b + k);
          values[slot] = lambda * derivativeProduct<D>(axes, p, q, i, k) +
                         mu * derivativeProduct<D>(axes, p, q, k, i) + (i == k ? mu * trace : 0);
          ++slot;
        }
      }
    }
  }
  out.stiffness = Eigen::Map<const SparseMatrix>(dofs, dofs, static_cast<int>(rows.size()), columnStart.data(),
                                                 rows.data(), values.data());

  // Facets: one per face a boundary particle lies on, with area int_face W_a.
  BoundaryFacets<D>& facets = out.facets;
  facets.offsets.assign(1, 0);
  for (Index a = 0; a < n; ++a) {
    const std::array<Index, D>& p = lattice.node[static_cast<std::size_t>(a)];
    for (int face = 0; face < 2 * D; ++face) {
      const int axis = faceAxis(face);
      const Index end = faceSign(face) < 0 ? 0 : lattice.intervals[static_cast<std::size_t>(axis)];
      if (p[static_cast<std::size_t>(axis)] != end) continue;
      Real area = 1;
      for (int ax = 0; ax < D; ++ax)
        if (ax != axis) area *= axes[static_cast<std::size_t>(ax)].lumped(p[static_cast<std::size_t>(ax)]);
      Vec<D> normal = Vec<D>::Zero();
      normal[axis] = faceSign(face);
      facets.particle.push_back(a);
      facets.face.push_back(face);
      facets.normal.push_back(normal);
      facets.area.push_back(area);
      facets.areaFraction.push_back(area / std::pow(lattice.spacing, D - 1));
      facets.planeSum.push_back(0);
    }
    facets.offsets.push_back(facets.count());
  }

  // T_{a f} = int_face W_a W_b I for facet f of particle b on the face: the face's consistent mass.
  std::vector<Triplet> triplets;
  for (Index f = 0; f < facets.count(); ++f) {
    const Index b = facets.particle[static_cast<std::size_t>(f)];
    const int face = facets.face[static_cast<std::size_t>(f)], axis = faceAxis(face);
    const std::array<Index, D>& q = lattice.node[static_cast<std::size_t>(b)];
    for (const Index a : latticeNeighbours<D>(lattice, q)) {
      const std::array<Index, D>& p = lattice.node[static_cast<std::size_t>(a)];
      if (p[static_cast<std::size_t>(axis)] != q[static_cast<std::size_t>(axis)]) continue;
      Real weight = 1;
      for (int ax = 0; ax < D; ++ax)
        if (ax != axis)
          weight *= axes[static_cast<std::size_t>(ax)].mass(p[static_cast<std::size_t>(ax)], q[static_cast<std::size_t>(ax)]);
      for (int i = 0; i < D; ++i) triplets.emplace_back(static_cast<int>(D * a + i), static_cast<int>(D * f + i), weight);
    }
  }
  out.tractionMatrix.resize(dofs, static_cast<int>(D * facets.count()));
  out.tractionMatrix.setFromTriplets(triplets.begin(), triplets.end());
  return out;
}

template LatticeNodes<1> latticeNodes<1>(const ParticleSet<1>&);
template LatticeNodes<2> latticeNodes<2>(const ParticleSet<2>&);
template LatticeNodes<3> latticeNodes<3>(const ParticleSet<3>&);
template GalerkinLattice<1> assembleGalerkinLattice<1>(const ParticleSet<1>&, const Material&);
template GalerkinLattice<2> assembleGalerkinLattice<2>(const ParticleSet<2>&, const Material&);
template GalerkinLattice<3> assembleGalerkinLattice<3>(const ParticleSet<3>&, const Material&);

}  // namespace mfwave
