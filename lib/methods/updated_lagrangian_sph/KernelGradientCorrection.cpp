#include "methods/updated_lagrangian_sph/KernelGradientCorrection.hpp"

#include "methods/updated_lagrangian_sph/ParallelThreshold.hpp"

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
  for (Index i = 0; i < n; ++i) {
    Mat<D> moment = Mat<D>::Zero();
    view.forEachPair(i, [&](Index, Index j, const Vec<D>& r, const Vec<D>& gradW) MFWAVE_INLINE_LAMBDA {
      moment.noalias() -= view.volume[j] * r * gradW.transpose();
    });
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
