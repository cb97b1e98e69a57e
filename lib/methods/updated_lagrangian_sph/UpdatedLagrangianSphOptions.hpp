#pragma once
// Options of the updated-Lagrangian SPH for solids (primer by Li, eqs. 17-30; docs/references.md).
// Every artificial term is a key with a neutral default where the physics allows, so its effect can
// be measured from a scene alone.

#include "core/Material.hpp"
#include "core/Types.hpp"

#include <array>
#include <functional>
#include <string>

namespace mfwave {

// How the density is obtained: summation over neighbours (eq. 17) or the continuity equation
// (eq. 18). Continuity is the default for solids: summation loses half the support at a free
// surface, which reads as a large tension there.
enum class DensityUpdate { Summation, Continuity };

// Monaghan's artificial viscosity Pi_ij (eq. 29-30): active only for approaching pairs,
//   Pi_ij = (-alpha cbar mu_ij + beta mu_ij^2) / rhobar,  mu_ij = h v_ij . x_ij / (|x_ij|^2 + eta^2 h^2).
struct ArtificialViscosityOptions {
  Real alpha = 0.1;
  Real beta = 0;
  Real eta = 0.1;  // eta^2 h^2 keeps mu finite for coincident particles
};

// Monaghan-Gray artificial stress R_ij (eq. 30): R_ij = f_ij^n (R_i + R_j), f_ij = W(r_ij) / W(dp),
// with R_i built in the principal frame of sigma_i: R'_aa = -epsilon sigma'_aa / rho_i^2 where
// sigma'_aa > 0 (tension), else 0.
struct ArtificialStressOptions {
  bool enabled = false;
  Real epsilon = 0.3;
  Real exponent = 4;              // n
  Real referenceSpacing = 0;      // dp; 0 means the initial particle spacing (volume^(1/D))
};

struct UpdatedLagrangianSphOptions {
  // rho0, bulk modulus K and shear modulus G. The EOS reference sound speed is c0 = sqrt(K / rho0).
  // Dimensions below 3 are plane strain (2-D) and uniaxial strain (1-D): the deviatoric projection
  // uses the 3-D trace, so a 1-D bar carries waves at c_p and a 2-D plate is in plane strain.
  Material material = Material::fromLame(1, 1, 1);
  // Stiffened-gas EOS (eq. 20-21): p = c0^2 (rho - rho0) + (gamma - 1) rho e. gamma = 1 is the
  // isothermal EOS of low-speed solid mechanics.
  Real gamma = 1;
  std::string kernel = "cubic_spline";  // kernelNames(); cubic_spline, gaussian, wendland_c2, ...
  Real smoothingLengthRatio = 1.3;      // h / dp
  DensityUpdate density = DensityUpdate::Continuity;
  ArtificialViscosityOptions viscosity;
  ArtificialStressOptions artificialStress;
  // The kernel-gradient correction C_i (Randles-Libersky, Bonet-Lok) in the velocity gradient,
  // continuity, stress divergence and energy equation: linear velocity fields give exact strain
  // rates, also at free surfaces. Off reproduces the primer's equations as written.
  bool kernelGradientCorrection = false;
  // XSPH: dx_i/dt = v_i + epsilon sum_j m_j / rhobar_ij (v_j - v_i) W_ij; 0 is off.
  Real xsph = 0;
  // Body force per unit mass g (only the first D entries are used).
  std::array<Real, 3> bodyForce{0, 0, 0};
  // Neighbour lists are built with radius (1 + skin) kappa h and rebuilt only when some particle
  // has moved more than skin kappa h / 2 since the last build, so every pair within the support is
  // always listed.
  Real neighbourSkin = 0.2;
  // Which pairs of particles the material connects (by index): false across a crack, the visibility
  // criterion on the particles' reference positions (geometry/Cracks). Asked for every listed pair
  // at each rebuild of the lists, so a crack costs nothing between rebuilds. Empty: every pair.
  std::function<bool(Index, Index)> interacts;
  // Time-step criteria (Monaghan): dt = min(courant h / (c + 1.2 (alpha c + beta max mu)),
  // forceFactor sqrt(h / max |a|)).
  Real courant = 0.3;
  Real forceFactor = 0.25;
};

}  // namespace mfwave
