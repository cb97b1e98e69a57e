#include "methods/updated_lagrangian_sph/Diagnostics.hpp"

#include "methods/updated_lagrangian_sph/ParallelThreshold.hpp"
#include "methods/updated_lagrangian_sph/StressVoigt.hpp"

#include <cmath>
#include <limits>
#include <vector>

namespace mfwave {

template <int D>
UpdatedLagrangianSphEnergy stateEnergy(const ParticleView<D>& view, const Real* e, const StiffenedGasEos& eos,
                                       Real shearModulus) {
  constexpr int S = D * (D + 1) / 2;
  UpdatedLagrangianSphEnergy energy;
  for (Index i = 0; i < view.count; ++i) {
    const Real m = view.m[i];
    const Real rho = view.rho[i];
    energy.kinetic += 0.5 * m * view.velocity(i).squaredNorm();
    energy.internal += m * e[i];
    energy.strain +=
        m * (deviatoricContraction<D>(view.s + i * S) / (4 * shearModulus * rho) + eos.storedEnergyPerMass(rho));
  }
  return energy;
}

template <int D>
ZeroEnergyModeIndicator zeroEnergyModeIndicator(const ParticleView<D>& view, Real spacing) {
  const Index n = view.count;
  const Kernel& kernel = *view.kernel;
  std::vector<Real> deviation(static_cast<std::size_t>(n));
  std::vector<Real> closest(static_cast<std::size_t>(n));
  Real* dev = deviation.data();
  Real* near = closest.data();
#pragma omp parallel for if (n > kParallelParticles) schedule(static)
  for (Index i = 0; i < n; ++i) {
    const Vec<D> xi = view.position(i);
    Vec<D> weighted = Vec<D>::Zero();
    Real weight = 0;
    Real nearest2 = std::numeric_limits<Real>::infinity();
    for (Index j : view.neighbours->row(i)) {
      const Vec<D> r = xi - view.position(j);
      if (j != i) nearest2 = std::min(nearest2, r.squaredNorm());
      const Real w = view.m[j] / view.rho[j] * kernel.value(r);
      weighted += w * view.velocity(j);
      weight += w;
    }
    const Vec<D> average = weight > 0 ? Vec<D>(weighted / weight) : Vec<D>::Zero();
    dev[i] = view.m[i] * (view.velocity(i) - average).squaredNorm();
    near[i] = nearest2;
  }
  ZeroEnergyModeIndicator indicator;
  Real deviationSum = 0;
  Real kineticSum = 0;
  Real worst = -1;
  Real nearest2 = std::numeric_limits<Real>::infinity();
  for (Index i = 0; i < n; ++i) {
    deviationSum += dev[i];
    kineticSum += view.m[i] * view.velocity(i).squaredNorm();
    if (dev[i] > worst) {
      worst = dev[i];
      indicator.zigzagWorstParticle = i;
    }
    nearest2 = std::min(nearest2, near[i]);
  }
  indicator.zigzag = kineticSum > 0 ? std::sqrt(deviationSum / kineticSum) : 0.0;
  if (!(kineticSum > 0)) indicator.zigzagWorstParticle = -1;
  indicator.minimumSpacingRatio = std::sqrt(nearest2) / spacing;
  return indicator;
}

template UpdatedLagrangianSphEnergy stateEnergy<1>(const ParticleView<1>&, const Real*, const StiffenedGasEos&, Real);
template UpdatedLagrangianSphEnergy stateEnergy<2>(const ParticleView<2>&, const Real*, const StiffenedGasEos&, Real);
template UpdatedLagrangianSphEnergy stateEnergy<3>(const ParticleView<3>&, const Real*, const StiffenedGasEos&, Real);
template ZeroEnergyModeIndicator zeroEnergyModeIndicator<1>(const ParticleView<1>&, Real);
template ZeroEnergyModeIndicator zeroEnergyModeIndicator<2>(const ParticleView<2>&, Real);
template ZeroEnergyModeIndicator zeroEnergyModeIndicator<3>(const ParticleView<3>&, Real);

}  // namespace mfwave
