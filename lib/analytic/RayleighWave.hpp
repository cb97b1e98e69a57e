#pragma once
// The Rayleigh wave speed of a homogeneous isotropic solid, for the exact half-space solutions
// (LambStripLoad's surface pole, HalfSpaceFrequencyWavenumber's wavenumber cut-off).

#include "core/Types.hpp"

namespace mfwave {

// c_R = c_s sqrt(xi), xi in (0, 1) the root of (2 - xi)^2 - 4 sqrt(1 - xi c_s^2/c_p^2) sqrt(1 - xi)
// divided by xi (which drops the root xi = 0), by bisection to rounding. Needs c_p > c_s > 0.
Real rayleighWaveSpeed(Real pWaveSpeed, Real shearWaveSpeed);

}  // namespace mfwave
