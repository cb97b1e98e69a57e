#include "PlateModes.hpp"

#include "PlateLattice.hpp"

#include "numerics/RestModes.hpp"
#include "core/Stopwatch.hpp"
#include "methods/updated_lagrangian_sph/UpdatedLagrangianSph.hpp"

#include <algorithm>
#include <cmath>

namespace mfwave::plate {

PlateModesResult linearisedPlateModes(const PlateStudy& study, Index rows) {
  const Stopwatch clock;
  const PlateLattice lattice = cellCentredPlate(study.length, study.thickness, study.lowerY, rows, study.clampLayers);
  UpdatedLagrangianSphOptions options = study.sph;
  options.viscosity.alpha = 0;  // no velocity at rest: the viscosity has nothing to act on anyway
  options.viscosity.beta = 0;
  options.artificialStress.enabled = false;  // R is not differentiable at zero stress
  UpdatedLagrangianSph<2> system(lattice.particles, options);
  system.fixParticles(lattice.clamp);
  const Vector rest = system.initialState(Vector());

  std::vector<bool> clamped(static_cast<std::size_t>(lattice.particles.physicalCount()), false);
  for (Index i : lattice.clamp) clamped[static_cast<std::size_t>(i)] = true;
  std::vector<Index> velocities;
  for (Index i = 0; i < lattice.particles.physicalCount(); ++i)
    if (!clamped[static_cast<std::size_t>(i)])
      for (int a = 0; a < 2; ++a) velocities.push_back(system.layout().velocity(i, a));

  const RestModes modes = restModes(restOperator(system, 0, rest, velocities));
  PlateModesResult result;
  result.rows = rows;
  result.unknowns = static_cast<Index>(velocities.size());
  // The lowest frequencies can be spurious near-null modes of the particle gradient; the first
  // bending mode is the lowest one above 1 % of the thin-plate frequency.
  const CantileverPlate plate(study.length, study.thickness, study.scene.material.material());
  const Real floor = 0.01 * 2 * kPi / plate.period();
  std::vector<Real> bending;
  for (Real w : modes.frequencies)
    if (w > floor) bending.push_back(w);
  result.firstPeriod = bending.empty() ? std::nan("") : 2 * kPi / bending[0];
  result.secondPeriod = bending.size() < 2 ? std::nan("") : 2 * kPi / bending[1];
  result.largestGrowthRate = modes.largestGrowthRate;
  result.zeroModes = modes.zeroModes + static_cast<Index>(modes.frequencies.size() - bending.size());
  result.seconds = clock.seconds();
  return result;
}

}  // namespace mfwave::plate
