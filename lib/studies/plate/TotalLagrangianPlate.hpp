#pragma once
// The plate by the total-Lagrangian SPH (lib/methods/total_lagrangian_sph): the same cell-centred
// particles and clamp columns as the updated-Lagrangian cases, kernels, neighbours and corrections
// fixed in the reference configuration, Saint Venant-Kirchhoff stress (large rotations), the
// variational hourglass penalty at study.total_lagrangian_hourglass times Young's modulus, no
// artificial viscosity or stress; central differences at study.total_lagrangian_cfl of the step
// 2 / omega_max of the system linearised about rest. The energy it records (kinetic + strain +
// penalty) is conserved by the scheme: its drift is the time integration's.

#include "PlateCase.hpp"

namespace mfwave::plate {

PlateCaseResult runTotalLagrangianPlateCase(const PlateStudy& study, const PlateCaseSettings& settings,
                                            const std::string& folder, bool progress);

}  // namespace mfwave::plate
