#include "methods/updated_lagrangian_sph/ForcePass.hpp"

#include "methods/updated_lagrangian_sph/ArtificialStress.hpp"
#include "methods/updated_lagrangian_sph/ParallelThreshold.hpp"

#include <algorithm>
#include <cmath>

namespace mfwave {

template <int D>
void forceRates(const ParticleView<D>& view, const ForceInputs<D>& inputs, const ForceOutputs<D>& outputs) {
  const Index n = view.count;
  const Kernel& kernel = *view.kernel;
  const Real support2 = kernel.supportRadius() * kernel.supportRadius();
  const ArtificialViscosity& viscosity = inputs.viscosity;
  const bool viscous = viscosity.active();
  const bool artificialStress = inputs.artificialStress != nullptr;
  const Mat<D>* A = inputs.stressOverRho2;
  const Real* P = inputs.pressureOverRho2;
  const bool corrected = view.correction != nullptr;
  // Gather form: row i only writes particle i's outputs, so the result does not depend on threads.
#pragma omp parallel for if (n > kParallelParticles) schedule(static)
  for (Index i = 0; i < n; ++i) {
    const Vec<D> xi = view.position(i);
    const Vec<D> vi = view.velocity(i);
    Vec<D> acceleration = Vec<D>::Zero();
    Mat<D> velocityMoment = Mat<D>::Zero();  // sum_j m_j v_ij grad W^T
    Real pressureWork = 0;                   // sum_j m_j (P_i + P_j + Pi_ij) v_ij . grad W
    Real viscousWork = 0;                    // sum_j m_j Pi_ij v_ij . grad W
    Real artificialWork = 0;                 // sum_j m_j v_ij . T_ij grad W
    Real largestMu = 0;
    for (Index j : view.neighbours->row(i)) {
      if (j == i) continue;
      const Vec<D> r = xi - view.position(j);
      const Real r2 = r.squaredNorm();
      if (r2 >= support2) continue;  // listed through the skin but outside the support
      const Vec<D> gradW = kernel.gradient(r);
      const Vec<D> vij = vi - view.velocity(j);
      const Real mj = view.m[j];
      Real pi = 0;
      if (viscous) {
        const Real mu = viscosity.mu(vij.dot(r), r2);
        if (mu != 0) {
          pi = viscosity.pi(mu, 0.5 * (inputs.soundSpeed[i] + inputs.soundSpeed[j]), 0.5 * (view.rho[i] + view.rho[j]));
          largestMu = std::max(largestMu, std::abs(mu));
        }
      }
      // Li eq. (30); corrected: A_i C_i grad W + A_j C_j grad W (ForcePass.hpp).
      Vec<D> force = corrected ? Vec<D>(A[i] * view.correction[i] * gradW + A[j] * view.correction[j] * gradW)
                               : Vec<D>((A[i] + A[j]) * gradW);
      force -= pi * gradW;
      if (artificialStress) {
        const Real weight = artificialStressWeight(kernel.value(r), inputs.inverseReferenceKernel,
                                                   inputs.artificialStressExponent);
        const Vec<D> extra = weight * ((inputs.artificialStress[i] + inputs.artificialStress[j]) * gradW);
        force += extra;
        artificialWork += mj * vij.dot(extra);
      }
      acceleration += mj * force;
      const Real vDotGrad = vij.dot(gradW);
      velocityMoment.noalias() += mj * vij * view.correctedGradient(i, gradW).transpose();
      pressureWork += mj * (P[i] + P[j] + pi) * vDotGrad;
      viscousWork += mj * pi * vDotGrad;
    }
    for (int a = 0; a < D; ++a) outputs.acceleration[i * D + a] = acceleration[a];
    if (corrected) {
      outputs.energyRate[i] =
          -(A[i].cwiseProduct(velocityMoment)).sum() + 0.5 * viscousWork - 0.5 * artificialWork;
    } else {
      // s_i / rho_i^2 = A_i + P_i I.
      Mat<D> deviatorOverRho2 = A[i];
      deviatorOverRho2.diagonal().array() += P[i];
      outputs.energyRate[i] =
          -(deviatorOverRho2.cwiseProduct(velocityMoment)).sum() + 0.5 * pressureWork - 0.5 * artificialWork;  // eq. (29)
    }
    outputs.viscousPower[i] = 0.5 * view.m[i] * viscousWork;
    outputs.artificialStressPower[i] = 0.5 * view.m[i] * artificialWork;
    outputs.largestMu[i] = largestMu;
  }
}

template void forceRates<1>(const ParticleView<1>&, const ForceInputs<1>&, const ForceOutputs<1>&);
template void forceRates<2>(const ParticleView<2>&, const ForceInputs<2>&, const ForceOutputs<2>&);
template void forceRates<3>(const ParticleView<3>&, const ForceInputs<3>&, const ForceOutputs<3>&);

}  // namespace mfwave
