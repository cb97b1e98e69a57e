#pragma once
// Options of the total-Lagrangian SPH for elastic solids (TotalLagrangianSph.hpp,
// docs/theory/total-lagrangian-sph.md).

#include "core/Material.hpp"
#include "core/Types.hpp"

#include <functional>
#include <string>

namespace mfwave {

struct TotalLagrangianSphOptions {
  // rho0 and the Lame constants of the Saint Venant-Kirchhoff law S = lambda tr(E) I + 2 mu E.
  // Below three dimensions: plane strain (2-D), uniaxial strain (1-D).
  Material material = Material::fromLame(1, 1, 1);
  std::string kernel = "cubic_spline";  // kernelNames()
  Real smoothingLengthRatio = 1.3;      // h / dp
  // The stiffness of the hourglass penalty, as a multiple of Young's modulus: the energy
  // (factor E / 2) sum_i V_i sum_j V_j w_ij |x_ij - F_i X_ij|^2 of the part of each pair's
  // relative position that particle i's deformation gradient does not explain. 0 is off.
  Real hourglassFactor = 1;
  // Which pairs of particles the material connects (by index): false across a crack (the visibility
  // criterion; the reference pairs are made once). Empty: every pair within the support.
  std::function<bool(Index, Index)> interacts;
};

}  // namespace mfwave
