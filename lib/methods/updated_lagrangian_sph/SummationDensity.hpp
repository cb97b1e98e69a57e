#pragma once
// Li eq. (17): rho_i = sum_j m_j W_ij over the neighbours of i (self included).

#include "methods/updated_lagrangian_sph/ParticleView.hpp"

namespace mfwave {

// rho[i] for every particle; view.rho is not read.
template <int D>
void summationDensity(const ParticleView<D>& view, Real* rho);

// rho_i of one particle, for accessors that need a single value.
template <int D>
Real summationDensityOf(const ParticleView<D>& view, Index i);

extern template void summationDensity<1>(const ParticleView<1>&, Real*);
extern template void summationDensity<2>(const ParticleView<2>&, Real*);
extern template void summationDensity<3>(const ParticleView<3>&, Real*);
extern template Real summationDensityOf<1>(const ParticleView<1>&, Index);
extern template Real summationDensityOf<2>(const ParticleView<2>&, Index);
extern template Real summationDensityOf<3>(const ParticleView<3>&, Index);

}  // namespace mfwave
