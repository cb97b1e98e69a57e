#include "methods/updated_lagrangian_sph/SummationDensity.hpp"

#include "kernels/KernelProfiles.hpp"
#include "methods/updated_lagrangian_sph/ParallelThreshold.hpp"

namespace mfwave {

namespace {

// rho_i with W from `kernel` (the view's kernel, virtual or inlined: the same values).
template <int D, class K>
Real densityOf(const ParticleView<D>& view, const K& kernel, Index i) {
  const Vec<D> xi = view.position(i);
  Real rho = 0;
  for (Index j : view.neighbours->row(i)) rho += view.m[j] * kernel.value(Vec<D>(xi - view.position(j)));
  return rho;  // Li eq. (17)
}

}  // namespace

template <int D>
Real summationDensityOf(const ParticleView<D>& view, Index i) {
  return densityOf<D>(view, *view.kernel, i);
}

template <int D>
void summationDensity(const ParticleView<D>& view, Real* rho) {
  const Index n = view.count;
  visitInlineKernel(*view.kernel, [&](const auto& kernel) {
#pragma omp parallel for if (n > kParallelParticles) schedule(static)
    for (Index i = 0; i < n; ++i) rho[i] = densityOf<D>(view, kernel, i);
  });
}

template void summationDensity<1>(const ParticleView<1>&, Real*);
template void summationDensity<2>(const ParticleView<2>&, Real*);
template void summationDensity<3>(const ParticleView<3>&, Real*);
template Real summationDensityOf<1>(const ParticleView<1>&, Index);
template Real summationDensityOf<2>(const ParticleView<2>&, Index);
template Real summationDensityOf<3>(const ParticleView<3>&, Index);

}  // namespace mfwave
