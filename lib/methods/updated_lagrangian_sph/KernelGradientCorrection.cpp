#include "methods/updated_lagrangian_sph/KernelGradientCorrection.hpp"

#include "methods/updated_lagrangian_sph/PairSweep.hpp"

#include <Eigen/LU>

#include <cmath>

namespace mfwave {

template <int D>
void kernelGradientCorrection(const ParticleView<D>& view, Mat<D>* correction) {
  const Index n = view.count;
  // A full support gives M = I, a flat free surface about diag(1, 1/2), a 3-D corner about I / 2.
  // A particle that has lost most of its neighbours (a fragment, a line of particles) has a near
  // singular M, and its inverse would amplify noise: it keeps C = I when an entry of M^{-1} would
  // exceed this.
  constexpr Real largestCorrection = 10;
#pragma omp parallel for if (n > kParallelParticles) schedule(static)
  for (Index i = 0; i < n; ++i) correction[i] = Mat<D>::Zero();
  // M_i summed into correction[], each pair once and in an order that does not depend on the
  // threads (PairSweep.hpp): x_ji grad_j W_ji^T = x_ij grad_i W_ij^T, so both rows take the same
  // product with the other side's volume.
  const Index* indices = view.neighbours->indices.data();
  const std::uint8_t* inside = view.pairs->inside.data();
  const Real* factor = view.pairs->gradientFactor.data();
  pair_sweep::forEachRowInBlocks(*view.pairs, n, [&](Index i) MFWAVE_INLINE_LAMBDA {
    const Vec<D> xi = view.position(i);
    const Real Vi = view.volume[i];
    const Index end = view.neighbours->offsets[static_cast<std::size_t>(i) + 1];
    Mat<D> moment = correction[i];
    for (Index k = view.pairs->first[static_cast<std::size_t>(i)], e = view.pairs->offsets[static_cast<std::size_t>(i)];
         k < end; ++k, ++e) {
      if (inside[e] == 0) continue;
      const Index j = indices[k];
      const Vec<D> r = xi - view.position(j);
      const Vec<D> gradW = factor[e] * r;
      moment.noalias() -= (view.volume[j] * r) * gradW.transpose();
      correction[j].noalias() -= (Vi * r) * gradW.transpose();
    }
    correction[i] = moment;
  });
#pragma omp parallel for if (n > kParallelParticles) schedule(static)
  for (Index i = 0; i < n; ++i) {
    const Mat<D> moment = correction[i];
    const Real determinant = moment.determinant();
    correction[i] = Mat<D>::Identity();
    if (std::abs(determinant) > 1e-12) {
      const Mat<D> inverse = moment.inverse();
      if (inverse.cwiseAbs().maxCoeff() <= largestCorrection) correction[i] = inverse.transpose();
    }
  }
}

template void kernelGradientCorrection<1>(const ParticleView<1>&, Mat<1>*);
template void kernelGradientCorrection<2>(const ParticleView<2>&, Mat<2>*);
template void kernelGradientCorrection<3>(const ParticleView<3>&, Mat<3>*);

}  // namespace mfwave
