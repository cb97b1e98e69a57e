#pragma once
// The boundary kernel correction of Ding-Long-Wu eqs. (28)-(29): W~_ab = alpha_a W_ab with
// alpha_a = 1 / sum_b W_ab V_b over the physical neighbours (the particles that carry unknowns).
// Multiplying row a of eq. (23) by alpha_a is the same as a lumped mass rho / alpha_a.

#include "core/Types.hpp"
#include "kernels/Kernel.hpp"
#include "neighbours/NeighbourList.hpp"
#include "particles/ParticleSet.hpp"

#include <vector>

namespace mfwave {

// alpha_a for every physical particle; `volumes` holds V_b of the physical particles.
// correction = false gives alpha = 1. Throws InputError("volumes") for a wrong length.
template <int D>
std::vector<Real> kernelCorrectionFactors(const ParticleSet<D>& particles, const NeighbourList& neighbours,
                                          const Kernel& kernel, const std::vector<Real>& volumes, bool correction);

}  // namespace mfwave
