#pragma once
// Monaghan's artificial viscosity Pi_ij of Li eq. (29)-(30):
//   mu_ij = h v_ij . x_ij / (|x_ij|^2 + eta^2 h^2),
//   Pi_ij = (-alpha cbar_ij mu_ij + beta mu_ij^2) / rhobar_ij  for approaching pairs (v_ij . x_ij < 0),
//   0 otherwise; v_ij = v_i - v_j, x_ij = x_i - x_j, bars are pair means.
// Pi_ij is symmetric in i, j and enters the momentum equation as an isotropic pressure, so it
// conserves linear and angular momentum and (through the energy equation) total energy.

#include "core/Types.hpp"

namespace mfwave {

struct ArtificialViscosity {
  Real alpha = 0;
  Real beta = 0;
  Real h = 1;
  Real eta2h2 = 0;  // eta^2 h^2

  bool active() const { return alpha > 0 || beta > 0; }

  // mu_ij for an approaching pair, 0 for a receding one.
  Real mu(Real velocityDotSeparation, Real distanceSquared) const {
    if (!(velocityDotSeparation < 0)) return 0;
    return h * velocityDotSeparation / (distanceSquared + eta2h2);
  }

  // Pi_ij from mu_ij and the pair means of the sound speed and density.
  Real pi(Real mu, Real meanSoundSpeed, Real meanDensity) const {
    return (-alpha * meanSoundSpeed * mu + beta * mu * mu) / meanDensity;
  }
};

}  // namespace mfwave
