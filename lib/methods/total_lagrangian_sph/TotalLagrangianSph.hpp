#pragma once
// Total-Lagrangian SPH for elastic solids: the semi-discrete system u'' = a(u) over particles
// that keep their reference neighbours, kernel gradients and corrections for the whole run
// (ReferencePairs.hpp); docs/theory/total-lagrangian-sph.md. One evaluation:
//   deformation   F_i = I + sum_j V_j (u_j - u_i) (B_i grad_i W_ij)^T   (corrected, exact for affine u)
//   stress        Saint Venant-Kirchhoff: E = (F^T F - I) / 2, S = lambda tr(E) I + 2 mu E, P = F S
//   momentum      rho0 a_i = sum_j V_j (P_i B_i + P_j B_j) grad_i W_ij   + hourglass force
//   hourglass     f_i = c E_Y V_i sum_j V_j w_ij (r_ij - r_ji),  r_ij = u_j - u_i - G_i (X_j - X_i),
//                 G = F - I, w_ij = -W'(r) / r
// Both forces are minus the gradient of one energy, sum_i V_i psi(F_i) plus the penalty
// c E_Y / 2 sum_i V_i sum_j V_j w_ij |r_ij|^2 (the second because G_i is the least-squares fit of
// the r_ij, so its own variation drops out), so a symplectic integrator keeps the total energy
// bounded, each pair term is antisymmetric (momentum is conserved), and the penalty vanishes for
// every affine field, at free surfaces too. The kernel is evaluated in the reference configuration
// only: no tensile instability, hence no artificial stress, and no artificial viscosity.
// Clamped particles keep u = 0 (a = 0) but take part in every sum.

#include "core/Types.hpp"
#include "methods/total_lagrangian_sph/ReferencePairs.hpp"
#include "methods/total_lagrangian_sph/TotalLagrangianSphOptions.hpp"
#include "particles/ParticleSet.hpp"
#include "systems/SecondOrderSystem.hpp"

#include <vector>

namespace mfwave {

struct TotalLagrangianSphEnergy {
  Real kinetic = 0;    // sum 1/2 rho0 V |v|^2
  Real strain = 0;     // sum V psi(F)
  Real hourglass = 0;  // the penalty's energy
  Real total() const { return kinetic + strain + hourglass; }
};

template <int D>
class TotalLagrangianSph : public SecondOrderSystem {
 public:
  // Throws InputError naming the option (kernel, smoothing_length_ratio, hourglass_factor) or
  // "particles" (ReferencePairs.hpp).
  TotalLagrangianSph(const ParticleSet<D>& particles, TotalLagrangianSphOptions options);

  const TotalLagrangianSphOptions& options() const { return options_; }
  Index particleCount() const { return pairs_.count(); }
  Real smoothingLength() const { return smoothingLength_; }
  Real meanNeighbourCount() const;  // pairs per particle inside the support, self excluded
  const ReferencePairs<D>& pairs() const { return pairs_; }

  // Clamped particles: a = 0; their entries of u and v are the caller's (zero them: clamp()).
  void fixParticles(const std::vector<Index>& particles);
  void clamp(Vector& field) const;

  // --- SecondOrderSystem ---
  Index size() const override { return pairs_.count() * D; }
  void acceleration(Real t, Eigen::Ref<const Vector> u, Eigen::Ref<const Vector> v, Eigen::Ref<Vector> a) override;
  bool dependsOnVelocity() const override { return false; }

  TotalLagrangianSphEnergy energy(const Vector& u, const Vector& v);

  // omega_max^2 of the system linearised about rest (power iteration on a(eps u) / eps), for the
  // central-difference step 2 / omega_max.
  Real largestFrequencySquared();

 private:
  // F_i - I for every particle, and P_i B_i.
  void deformation(const Real* u);

  TotalLagrangianSphOptions options_;
  ReferencePairs<D> pairs_;
  Real smoothingLength_ = 0;
  std::vector<unsigned char> fixed_;
  std::vector<Mat<D>> displacementGradient_;  // G_i = F_i - I of the last evaluation
  std::vector<Mat<D>> stressTimesCorrection_;  // P_i B_i of the last evaluation
};

extern template class TotalLagrangianSph<1>;
extern template class TotalLagrangianSph<2>;
extern template class TotalLagrangianSph<3>;

}  // namespace mfwave
