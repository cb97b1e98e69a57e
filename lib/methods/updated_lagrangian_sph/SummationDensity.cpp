#include "methods/updated_lagrangian_sph/SummationDensity.hpp"

#include "methods/updated_lagrangian_sph/ParallelThreshold.hpp"

namespace mfwave {

template <int D>
Real summationDensityOf(const ParticleView<D>& view, Index i) {
  const Vec<D> xi = view.position(i);
  Real rho = 0;
  for (Index j : view.neighbours->row(i)) rho += view.m[j] * view.kernel->value(Vec<D>(xi - view.position(j)));
  return rho;  // Li eq. (17)
}

template <int D>
void summationDensity(const ParticleView<D>& view, Real* rho) {
  const Index n = view.count;
#pragma omp parallel for if (n > kParallelParticles) schedule(static)
  for (Index i = 0; i < n; ++i) rho[i] = summationDensityOf(view, i);
}

template void summationDensity<1>(const ParticleView<1>&, Real*);
template void summationDensity<2>(const ParticleView<2>&, Real*);
template void summationDensity<3>(const ParticleView<3>&, Real*);
template Real summationDensityOf<1>(const ParticleView<1>&, Index);
template Real summationDensityOf<2>(const ParticleView<2>&, Index);
template Real summationDensityOf<3>(const ParticleView<3>&, Index);

}  // namespace mfwave
