#include "methods/total_lagrangian_sph/ReferencePairs.hpp"

#include "core/Error.hpp"
#include "neighbours/CellList.hpp"
#include "neighbours/NeighbourList.hpp"

#include <Eigen/LU>

#include <cmath>
#include <string>

namespace mfwave {

template <int D>
ReferencePairs<D> makeReferencePairs(const ParticleSet<D>& particles, const Kernel& kernel,
                                     const std::function<bool(Index, Index)>& interacts) {
  if (particles.ghostCount() > 0)
    throw InputError("particles", "ghost particles are not supported: the total-Lagrangian SPH has free surfaces "
                                  "and the kernel-gradient correction in place of ghosts");
  const Index n = particles.physicalCount();
  if (n == 0) throw InputError("particles", "no physical particles");
  ReferencePairs<D> pairs;
  pairs.X.resize(static_cast<std::size_t>(n * D));
  pairs.volume.resize(static_cast<std::size_t>(n));
  for (Index i = 0; i < n; ++i) {
    const Real v = particles.volume[static_cast<std::size_t>(i)];
    if (!(v > 0) || !std::isfinite(v))
      throw InputError("particles", "particle " + std::to_string(i) + " has a non-positive volume");
    pairs.volume[static_cast<std::size_t>(i)] = v;
    for (int a = 0; a < D; ++a) pairs.X[static_cast<std::size_t>(i * D + a)] = particles.position(i)[a];
  }
  const Real support = kernel.supportRadius();
  const NeighbourList list = buildNeighbourList<D>(CellList<D>(particles, support), n);
  pairs.offsets.assign(static_cast<std::size_t>(n) + 1, 0);
  pairs.correction.resize(static_cast<std::size_t>(n));
  for (Index i = 0; i < n; ++i) {
    const Vec<D> xi = particles.position(i);
    Mat<D> moment = Mat<D>::Zero();
    for (Index j : list.row(i)) {
      if (j == i || (interacts && !interacts(i, j))) continue;
      const Vec<D> r = xi - particles.position(j);
      if (!(r.norm() < support)) continue;
      const Vec<D> g = kernel.gradient(r);
      if (g.squaredNorm() == 0) continue;  // a pair at the edge of the support carries nothing
      pairs.neighbour.push_back(j);
      for (int a = 0; a < D; ++a) pairs.gradient.push_back(g[a]);
      moment.noalias() -= pairs.volume[static_cast<std::size_t>(j)] * r * g.transpose();  // sum V_j X_ji grad W^T
    }
    pairs.offsets[static_cast<std::size_t>(i) + 1] = pairs.pairCount();
    Eigen::FullPivLU<Mat<D>> lu(moment);
    if (!lu.isInvertible() || std::abs(moment.determinant()) < 1e-8 * std::pow(moment.norm(), D))
      throw InputError("particles", "particle " + std::to_string(i) +
                                        " has fewer than " + std::to_string(D) +
                                        " independent neighbours in its kernel support: the kernel-gradient "
                                        "correction is undefined (a loose particle, or h too small)");
    pairs.correction[static_cast<std::size_t>(i)] = moment.inverse().transpose();
  }
  return pairs;
}

template ReferencePairs<1> makeReferencePairs<1>(const ParticleSet<1>&, const Kernel&,
                                                 const std::function<bool(Index, Index)>&);
template ReferencePairs<2> makeReferencePairs<2>(const ParticleSet<2>&, const Kernel&,
                                                 const std::function<bool(Index, Index)>&);
template ReferencePairs<3> makeReferencePairs<3>(const ParticleSet<3>&, const Kernel&,
                                                 const std::function<bool(Index, Index)>&);

}  // namespace mfwave
