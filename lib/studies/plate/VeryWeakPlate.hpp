#pragma once
// The plate by the very weak form SPH (Ding-Long-Wu, consistent variant), for the comparison of the
// two SPH families on one case at small deformation: the nodal lattice of [0, L] x [lowerY,
// lowerY + H] at dx = H / rows (rows + 1 nodes across the thickness, faces on the plate's
// surfaces), two ghost layers completing the kernel sums, the -x face clamped by prescribed zero
// displacements (eq. 30), the other faces free, the same first-mode start; central differences at a
// fraction of the operator's stable step. The method is linear (small strain, small rotation), so
// its period does not depend on V_f.

#include "PlateCase.hpp"

namespace mfwave::plate {

PlateCaseResult runVeryWeakPlateCase(const PlateStudy& study, const PlateCaseSettings& settings,
                                     const std::string& folder, bool progress);

}  // namespace mfwave::plate
