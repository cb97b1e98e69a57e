#pragma once
// The plate's small vibrations by the updated-Lagrangian SPH, linearised about rest
// (lib/numerics/RestModes): the first bending period of the discretisation itself, with no
// amplitude, no artificial terms (both vanish or are switched off in the linearisation) and no
// time integration. Over several resolutions it shows how the method converges, free of what the
// runs add (docs/studies/sph-solids.md).

#include "PlateCase.hpp"

namespace mfwave::plate {

struct PlateModesResult {
  Index rows = 0;             // H / dp
  Index unknowns = 0;         // velocity components of the free particles
  Real firstPeriod = 0;       // 2 pi / lowest nonzero omega
  Real secondPeriod = 0;      // the next mode (the second bending mode of a slender plate)
  Real largestGrowthRate = 0; // 0 for a stable operator (up to the finite differences' noise)
  Index zeroModes = 0;
  Real seconds = 0;
};

// The study's method options with the artificial viscosity and stress switched off; the clamp of
// study.clamp_layers fixed columns as in the runs.
PlateModesResult linearisedPlateModes(const PlateStudy& study, Index rows);

}  // namespace mfwave::plate
