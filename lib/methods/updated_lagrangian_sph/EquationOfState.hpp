#pragma once
// The stiffened-gas equation of state of Li's primer, eq. (20)-(21):
//   p = c0^2 (rho - rho0) + (gamma - 1) rho e,   c^2 = c0^2 + (gamma - 1) (e + p / rho),
// with c0^2 = K / rho0 and K the 3-D bulk modulus, so that at small strain p = -K tr(eps) in
// every dimension (the deviatoric part carries the rest of the plane-strain / uniaxial-strain
// stiffness). gamma = 1 is the isothermal EOS of low-speed solid mechanics; then c = c0.

#include "core/Types.hpp"

#include <algorithm>
#include <cmath>

namespace mfwave {

struct StiffenedGasEos {
  Real rho0 = 1;
  Real c0Squared = 1;
  Real gamma = 1;

  // Li eq. (20).
  Real pressure(Real rho, Real e) const { return c0Squared * (rho - rho0) + (gamma - 1) * rho * e; }

  // Li eq. (21). c^2 is clamped at 0: a strongly expanded, cold gas-like state would otherwise give
  // a NaN speed; with gamma = 1 the formula is c0 exactly.
  Real soundSpeed(Real rho, Real e) const {
    if (gamma == 1) return std::sqrt(c0Squared);
    const Real p = pressure(rho, e);
    return std::sqrt(std::max<Real>(0, c0Squared + (gamma - 1) * (e + p / rho)));
  }

  // Energy per unit mass stored by the cold (gamma = 1) part of the EOS: the integral of
  // p / rho^2 d rho from rho0, c0^2 (ln(rho / rho0) + rho0 / rho - 1). Exact for gamma = 1; for
  // gamma > 1 the thermal part (gamma - 1) rho e is not stored elastic energy and is left out.
  Real storedEnergyPerMass(Real rho) const { return c0Squared * (std::log(rho / rho0) + rho0 / rho - 1); }
};

}  // namespace mfwave
