#pragma once
// Statistical (Shepard) volumes of the very weak form SPH, Ding-Long-Wu eqs. (4), (24)-(25).
//
// Ghost particles, if present, complete the kernel sums (they carry no unknowns): on a lattice with
// enough ghost layers, sum_b W_ab is the full-lattice sum for every particle, and the volume
// fraction FV_a supplies the part of the support that lies inside the body.

#include "core/Types.hpp"
#include "kernels/Kernel.hpp"
#include "neighbours/NeighbourList.hpp"
#include "particles/ParticleSet.hpp"

#include <vector>

namespace mfwave {

// FV_a of eq. (24) for the physical particles of a box: 2^-m for a particle on m box faces
// (1 interior, 1/2 face, 1/4 edge, 1/8 corner in 3-D). correction = false gives FV = 1 (eq. (4)).
template <int D>
std::vector<Real> volumeFractions(const ParticleSet<D>& particles, bool correction);

// sum_{b in M_a} W_ab for the physical particles a, over physical AND ghost neighbours, self
// included. `neighbours` must have a row for every physical particle (rows >= physicalCount())
// and a search radius of at least kernel.supportRadius(); throws InputError("neighbours") when the
// rows are missing and InputError("dimension") when the kernel's dimension is not D.
template <int D>
std::vector<Real> shepardSums(const ParticleSet<D>& particles, const NeighbourList& neighbours,
                              const Kernel& kernel);

// V_a = FV_a / sum_{b in M_a} W_ab, eq. (25) (eq. (4) with the correction off), physical particles.
template <int D>
std::vector<Real> statisticalVolumes(const ParticleSet<D>& particles, const NeighbourList& neighbours,
                                     const Kernel& kernel, bool volumeCorrection);

// Shared argument checks of the very weak form SPH functions.
template <int D>
void checkVeryWeakInputs(const ParticleSet<D>& particles, const NeighbourList& neighbours, const Kernel& kernel);

}  // namespace mfwave
