#pragma once
// The particles of the cantilever plate for the updated-Lagrangian SPH: a cell-centred lattice, so
// that n particles of spacing dp = H / n fill the thickness H exactly (particle j at
// y = lower + (j + 1/2) dp) and the plate's mass is rho L H. The clamp is `clampLayers` columns of
// the same lattice at x < 0 (x = -(k + 1/2) dp), whose particles are held fixed, as Gray, Monaghan
// and Swift clamp the plate between fixed particles: the plate starts at x = 0, and every free
// particle near the root has a full kernel support.

#include "core/Types.hpp"
#include "particles/ParticleSet.hpp"

#include <vector>

namespace mfwave::plate {

struct PlateLattice {
  ParticleSet<2> particles;     // row by row (x fastest), clamp columns first in each row
  std::vector<Index> clamp;     // the fixed particles (x < 0)
  std::vector<Index> tip;       // the last column (x = L - dp / 2), bottom to top
  Index columns = 0, rows = 0;  // of the plate alone (L / dp and H / dp)
  Real spacing = 0;
};

// Plate [0, length] x [lowerY, lowerY + thickness] with `rows` particles across the thickness.
PlateLattice cellCentredPlate(Real length, Real thickness, Real lowerY, Index rows, Index clampLayers);

}  // namespace mfwave::plate
