#include "methods/updated_lagrangian_sph/KinematicsPass.hpp"

#include "methods/updated_lagrangian_sph/JaumannStressRate.hpp"
#include "methods/updated_lagrangian_sph/ParallelThreshold.hpp"
#include "methods/updated_lagrangian_sph/StressVoigt.hpp"

namespace mfwave {

template <int D>
void kinematicsRates(const ParticleView<D>& view, const KinematicsSettings& settings,
                     const UpdatedLagrangianSphLayout<D>& layout, Real* qdot) {
  constexpr int S = UpdatedLagrangianSphLayout<D>::stressComponents;
  const Index n = view.count;
  const Kernel& kernel = *view.kernel;
  const Real support2 = kernel.supportRadius() * kernel.supportRadius();
  const bool xsph = settings.xsph > 0;
  // Gather form: row i only writes particle i's rates, so the result does not depend on threads.
#pragma omp parallel for if (n > kParallelParticles) schedule(static)
  for (Index i = 0; i < n; ++i) {
    const Vec<D> xi = view.position(i);
    const Vec<D> vi = view.velocity(i);
    const Real rhoi = view.rho[i];
    Mat<D> gradient = Mat<D>::Zero();
    Vec<D> smoothing = Vec<D>::Zero();
    Real densityRate = 0;
    for (Index j : view.neighbours->row(i)) {
      if (j == i) continue;
      const Vec<D> r = xi - view.position(j);
      const Real r2 = r.squaredNorm();
      if (r2 >= support2) continue;  // listed through the skin but outside the support
      const Vec<D> gradW = view.correctedGradient(i, kernel.gradient(r));
      const Vec<D> vji = view.velocity(j) - vi;
      gradient.noalias() += (view.m[j] / view.rho[j]) * vji * gradW.transpose();  // Li eq. (22)
      densityRate -= view.m[j] * vji.dot(gradW);                                  // Li eq. (18)
      if (xsph) smoothing += (2 * view.m[j] / (rhoi + view.rho[j]) * kernel.value(r)) * vji;
    }
    for (int a = 0; a < D; ++a) qdot[layout.position(i, a)] = vi[a] + settings.xsph * smoothing[a];
    qdot[layout.density(i)] = settings.continuity ? densityRate : 0.0;
    const Mat<D> s = stressFromVoigt<D>(view.s + i * S);
    stressToVoigt<D>(jaumannStressRate<D>(gradient, s, settings.shearModulus), qdot + layout.stress(i, 0));
  }
}

template void kinematicsRates<1>(const ParticleView<1>&, const KinematicsSettings&,
                                 const UpdatedLagrangianSphLayout<1>&, Real*);
template void kinematicsRates<2>(const ParticleView<2>&, const KinematicsSettings&,
                                 const UpdatedLagrangianSphLayout<2>&, Real*);
template void kinematicsRates<3>(const ParticleView<3>&, const KinematicsSettings&,
                                 const UpdatedLagrangianSphLayout<3>&, Real*);

}  // namespace mfwave
